-- LuaJIT twin (Lua 5.1 has no math.tointeger: the number itself, already integral) of conversions.st: REAL/LREAL <-> integer conversions (3M iterations).
-- REAL is a 32-bit float in ST; the scaled values here (multiples of 0.25
-- below 1024) are exact in both, so doubles give the same results.
-- REAL_TO_DINT rounds half to even (IEC), TRUNC truncates toward zero.
local function roundEven(x)
  local f = math.floor(x)
  local d = x - f
  if d > 0.5 then return f + 1 end
  if d < 0.5 then return f end
  if f % 2 == 0 then return f else return f + 1 end
end

local function trunc(x)
  if x >= 0 then return math.floor(x) else return math.ceil(x) end
end

local checksum = 0
local acc = 0.0
for i = 1, 3000000 do
  local raw = i % 4096
  local scaled = raw * 0.25
  local rounded = roundEven(scaled)
  acc = acc + rounded * 0.5
  local whole = trunc(acc / 1000.0)
  checksum = (checksum + rounded + (whole % 1000)) % 1000003
end
print(checksum)
