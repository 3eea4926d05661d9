-- Lua twin of strings.st: string building with concatenation, length and
-- taking the right-hand end, kept below the 255 characters of an ST STRING.
local checksum = 0
local s = ""
for k = 1, 4000000 do
  local m = k % 3
  if m == 0 then
    s = s .. "ab"
  elseif m == 1 then
    s = s .. "xyz"
  else
    s = s .. "Q"
  end
  if #s > 200 then
    s = s:sub(-10)
  end
  checksum = (checksum * 7 + #s) % 1000003
end
print(checksum)
