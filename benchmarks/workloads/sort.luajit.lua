-- LuaJIT twin (Lua 5.1 has no //: math.floor of the quotient, exact below 2^53) of sort.st: insertion sort of 2000 DINTs from a Park-Miller
-- generator (Schrage's method keeps every product inside 32 bits), repeated.
-- a[0] is a sentinel smaller than every value, so the inner loop needs no
-- bounds test.
local N = 2000
local ROUNDS = 25
local a = {}
local seed = 12345
local checksum = 0
for _ = 1, ROUNDS do
  a[0] = -1
  for k = 1, N do
    seed = 16807 * (seed % 127773) - 2836 * math.floor(seed / 127773)
    if seed <= 0 then seed = seed + 2147483647 end
    a[k] = seed % 1000000
  end
  for i = 2, N do
    local key = a[i]
    local j = i - 1
    while a[j] > key do
      a[j + 1] = a[j]
      j = j - 1
    end
    a[j + 1] = key
  end
  for k = 1, N do
    checksum = (checksum * 31 + a[k] % 1000) % 1000003
  end
end
print(checksum)
