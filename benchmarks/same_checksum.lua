-- Compares the checksum strun left in its --dump JSON with the one the Lua
-- twin printed. Usage: lua5.4 same_checksum.lua DUMP_FILE LUA_OUTPUT_FILE
-- Prints both values as "STRUN LUA"; exits 0 when they agree, 1 when they
-- differ or one is missing. Integers must be equal; reals may differ by a
-- relative 1e-12: both sides do the same IEEE double operations in the same
-- order, so only the number of printed digits may differ.

local function readAll(path)
  local file, err = io.open(path, "r")
  if not file then
    io.stderr:write("cannot read ", err, "\n")
    os.exit(1)
  end
  local text = file:read("a")
  file:close()
  return text
end

local dump = readAll(arg[1])
local luaOut = readAll(arg[2])

-- Every workload is one PROGRAM with a variable named exactly `checksum`;
-- look for it inside "programs" so a diagnostic text cannot be taken for it.
local programsAt = dump:find('"programs"', 1, true)
local strunText = programsAt and dump:match('"checksum"%s*:%s*"?([^,}%]%s"]+)', programsAt)
local luaText = luaOut:match("^%s*(%S+)")

io.write(tostring(strunText), " ", tostring(luaText), "\n")

local strunValue, luaValue = tonumber(strunText), tonumber(luaText)
if strunValue == nil or luaValue == nil then
  os.exit(1)
end
if math.type(strunValue) == "integer" and math.type(luaValue) == "integer" then
  os.exit(strunValue == luaValue and 0 or 1)
end
local scale = math.max(1.0, math.abs(luaValue))
os.exit(math.abs(strunValue - luaValue) <= 1e-12 * scale and 0 or 1)
