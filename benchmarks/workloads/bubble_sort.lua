-- Lua twin of bubble_sort.st: bubble sort of 400 DINTs from a Park-Miller
-- generator (Schrage's method), 150 rounds, a pass flag ending it early.
local N = 400
local a = {}
local seed = 4242
local checksum = 0
for _ = 1, 150 do
  for k = 1, N do
    seed = 16807 * (seed % 127773) - 2836 * (seed // 127773)
    if seed <= 0 then seed = seed + 2147483647 end
    a[k] = seed % 100000
  end
  local n = N - 1
  local swapped = true
  while swapped do
    swapped = false
    for j = 1, n do
      if a[j] > a[j + 1] then
        local t = a[j]
        a[j] = a[j + 1]
        a[j + 1] = t
        swapped = true
      end
    end
    n = n - 1
  end
  for k = 1, N do
    checksum = (checksum * 31 + a[k] % 1000) % 1000003
  end
end
print(checksum)
