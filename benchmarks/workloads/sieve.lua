-- Lua twin of sieve.st: sieve of Eratosthenes over 0..2000000, repeated.
-- Checksum: the number of primes found and their sum, folded together.
local N = 2000000
local ROUNDS = 4
local composite = {}
local checksum = 0
for _ = 1, ROUNDS do
  for i = 0, N do
    composite[i] = false
  end
  for i = 2, 1414 do -- 1414 = floor(sqrt(2000000))
    if not composite[i] then
      for j = i * i, N, i do
        composite[j] = true
      end
    end
  end
  local count = 0
  local sumMod = 0
  for i = 2, N do
    if not composite[i] then
      count = count + 1
      sumMod = (sumMod + i) % 1000003
    end
  end
  checksum = (checksum + count * 1000 + sumMod) % 1000000007
end
print(checksum)
