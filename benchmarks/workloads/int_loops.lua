-- Lua twin of int_loops.st: nested integer FOR loops, 25M iterations.
local checksum = 0
for i = 1, 5000 do
  for j = 1, 5000 do
    checksum = checksum + (i * j) % 7 + (i + j) % 3
  end
end
print(checksum)
