-- LuaJIT twin (Lua 5.1 has no //: math.floor of the quotient, exact below 2^53) of fb_calls.st: two chained instances of a small smoothing
-- function block, each called once per iteration (2 x 3M calls).
-- A function block instance is a table of its variables; its body is a
-- function of that table, as a Lua programmer would write it.
local function newSmoother()
  return { sample = 0, smoothed = 0, calls = 0, acc = 0 }
end

local function smootherBody(fb)
  fb.acc = fb.acc + fb.sample - math.floor(fb.acc / 8)
  fb.smoothed = math.floor(fb.acc / 8)
  fb.calls = fb.calls + 1
end

local first, second = newSmoother(), newSmoother()
local checksum = 0
for i = 1, 3000000 do
  first.sample = i % 1000
  smootherBody(first)
  second.sample = first.smoothed
  smootherBody(second)
  checksum = (checksum + second.smoothed) % 1000003
end
print(checksum)
