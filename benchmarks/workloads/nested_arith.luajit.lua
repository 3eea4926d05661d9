-- LuaJIT twin (Lua 5.1 has no //: math.floor of the quotient, exact below 2^53) of nested_arith.st: nested integer arithmetic in assignments and
-- conditions (4M iterations). Every operand of // and % is non-negative.
local x, y, z, h = 7, 1, 0, 0
for i = 1, 4000000 do
  if x % 2 == 0 then
    x = math.floor(x / 2)
  else
    x = 3 * x + 1
  end
  if x > 1000000 or x == 1 then
    x = i % 1000 + 7
  end
  y = (y * 31 + (x % 97) * 3 + 1) % 1000003
  z = ((x + y) % 1000 * 2 + (i % 7) * (y % 11)) % 65536
  h = (h + z * 3 - math.floor(z / 4) + 5) % 999983
end
print((h + y + x) % 1000003)
