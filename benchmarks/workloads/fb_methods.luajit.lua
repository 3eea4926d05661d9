-- LuaJIT twin (Lua 5.1 has no //: math.floor of the quotient, exact below 2^53) of fb_methods.st: a conveyor object owning two motor objects;
-- each step calls the conveyor's body (which steps both motors) and a method
-- of the conveyor that calls a method of each motor (1M steps).
-- ST's DINT / and MOD truncate toward zero; Lua's // and % floor, so the
-- twin uses helpers with ST semantics where operands can be negative.
local function idiv(a, b)
  local q = math.floor(a / b)
  if q < 0 and q * b ~= a then q = q + 1 end
  return q
end
local function imod(a, b) return a - idiv(a, b) * b end

local Motor = {}
Motor.__index = Motor
function Motor.new() return setmetatable({ demand = 0, speed = 0, wear = 0 }, Motor) end
function Motor:body()
  self.speed = self.speed + idiv(self.demand - self.speed, 4)
  self.wear = self.wear + imod(self.speed, 3)
end
function Motor:load(weight) return imod(self.speed * weight + self.wear, 9973) end

local Conveyor = {}
Conveyor.__index = Conveyor
function Conveyor.new()
  return setmetatable({ target = 0, throughput = 0, left = Motor.new(), right = Motor.new() }, Conveyor)
end
function Conveyor:body()
  self.left.demand = self.target
  self.left:body()
  self.right.demand = self.target + 10
  self.right:body()
  self.throughput = self.left.speed + self.right.speed
end
function Conveyor:balance(weight) return self.left:load(weight) - self.right:load(weight + 1) end

local line = Conveyor.new()
local checksum = 0
for n = 1, 1000000 do
  line.target = n % 500
  line:body()
  checksum = imod(checksum + line.throughput + line:balance(n % 13), 1000003)
  if checksum < 0 then checksum = checksum + 1000003 end
end
print(checksum)
