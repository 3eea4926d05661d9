-- LuaJIT twin (Lua 5.1 has no //: math.floor of the quotient, exact below 2^53) of collatz.st: total Collatz steps of 1..300000.
local checksum, longest = 0, 0
for start = 1, 300000 do
  local x, steps = start, 0
  while x ~= 1 do
    if x % 2 == 0 then x = math.floor(x / 2) else x = 3 * x + 1 end
    steps = steps + 1
  end
  if steps > longest then longest = steps end
  checksum = (checksum + steps) % 1000003
end
print(checksum)
