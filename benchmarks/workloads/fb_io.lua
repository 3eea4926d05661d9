-- Lua twin of fb_io.st: a function block with three inputs and three outputs
-- (a table of its variables and a body function), two chained instances
-- (2 x 2M calls).
local function newAccumulator()
  return { x = 0, w = 0, enable = false, total = 0, count = 0, high = false }
end

local function accumulatorBody(fb)
  if fb.enable then
    fb.total = (fb.total + fb.x * fb.w) % 1000003
    fb.count = fb.count + 1
  end
  fb.high = fb.total > 500000
end

local first, second = newAccumulator(), newAccumulator()
local highs, t = 0, 0
for i = 1, 2000000 do
  first.x = i % 100
  first.w = 3
  first.enable = i % 3 ~= 0
  accumulatorBody(first)
  second.x = first.total % 1000
  second.w = 2
  second.enable = first.high
  accumulatorBody(second)
  t = second.total
  if second.high then highs = highs + 1 end
end
print((highs + t + first.total + first.count + second.count) % 1000003)
