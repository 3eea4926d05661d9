-- Lua twin of many_args.st: FUNCTION calls with five and three arguments,
-- one nested in another's arguments, one in an IF condition (3 x 2M calls).
local function blend5(a, b, c, d, e)
  return (a * 7 + b * 3 + c + d * 2 + e) % 65521
end

local function max3(a, b, c)
  local m = a
  if b > m then m = b end
  if c > m then m = c end
  return m
end

local function inBand(v, lo, hi)
  return v >= lo and v <= hi
end

local checksum, hits, k = 0, 0, 17
for i = 1, 2000000 do
  checksum = blend5(checksum, i % 1000, i % 13, max3(i % 100, 50, k), 4)
  if inBand(checksum, 1000, 40000) then hits = hits + 1 end
  k = (k + 7) % 90
end
print(checksum + hits)
