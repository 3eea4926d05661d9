-- Lua twin of real_math.st: LREAL arithmetic.
-- Part 1: midpoint rule for the integral of 4 / (1 + x^2) over [0, 1] (= pi).
-- Part 2: Newton's iteration for the square roots of 1.0 .. 600000.0, 14 steps each.
-- The checksum weighs both parts so that each shows in its leading digits.
local steps = 20000000
local h = 1.0 / steps
local x = h * 0.5
local sum = 0.0
for _ = 1, steps do
  sum = sum + 4.0 / (1.0 + x * x)
  x = x + h
end
local piApprox = sum * h

local rootSum = 0.0
local c = 0.0
for _ = 1, 600000 do
  c = c + 1.0
  local root = 0.5 * (c + 1.0)
  for _ = 1, 14 do
    root = 0.5 * (root + c / root)
  end
  rootSum = rootSum + root
end
print(string.format("%.17g", piApprox * 1000000.0 + rootSum / 1000.0))
