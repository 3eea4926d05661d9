-- Lua twin of string_build.st: strings built piece by piece with .. and
-- tostring, their length and first two characters (50k strings of 25 pieces).
local checksum, matches = 0, 0
for i = 1, 50000 do
  local s = "n"
  for j = 1, 25 do
    s = s .. tostring((i + j * 7) % 97)
    if j % 5 == 0 then s = s .. "," end
  end
  if s:sub(1, 2) == "n1" then matches = matches + 1 end
  checksum = (checksum * 7 + #s) % 1000003
end
print(checksum + matches)
