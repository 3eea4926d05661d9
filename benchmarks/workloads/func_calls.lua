-- Lua twin of func_calls.st: a clamp-and-scale helper and a three-argument
-- mixer, each called once per iteration (2 x 3M calls).
local function clampScale(value, low, high, factor)
  if value < low then
    return low * factor
  elseif value > high then
    return high * factor
  else
    return value * factor
  end
end

local function mix(a, b, c)
  return (a * 3 + b * 5 + c) % 10007
end

local checksum = 0
for i = 1, 3000000 do
  local x = clampScale(i % 2000, 100, 1500, 3)
  checksum = mix(checksum, x, i % 7)
end
print(checksum)
