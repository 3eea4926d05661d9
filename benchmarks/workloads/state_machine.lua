-- Lua twin of state_machine.st: a batch-process state machine stepped
-- 5M times, driven by a small LCG as "sensor noise". ST's CASE becomes an
-- if/elseif chain; the enumeration becomes integer constants.
local IDLE, FILLING, HEATING, MIXING, DRAINING, CLEANING, FAULT = 0, 1, 2, 3, 4, 5, 6

local phase = IDLE
local noise = 1
local level, temp, timer = 0, 0, 0
local batches, faults = 0, 0
local checksum = 0
for _ = 1, 5000000 do
  noise = (noise * 75 + 74) % 65537
  local code
  if phase == IDLE then
    code = 1
    if noise % 4 == 0 then
      phase = FILLING
      level = 0
    end
  elseif phase == FILLING then
    code = 2
    level = level + 3 + noise % 5
    if level >= 100 then
      phase = HEATING
      temp = 20
    end
  elseif phase == HEATING then
    code = 3
    temp = temp + 1 + noise % 3
    if temp >= 80 then
      phase = MIXING
      timer = 0
    elseif noise % 1000 == 7 then
      phase = FAULT
    end
  elseif phase == MIXING then
    code = 4
    timer = timer + 1
    if timer >= 15 then
      phase = DRAINING
    end
  elseif phase == DRAINING then
    code = 5
    level = level - 7
    if level <= 0 then
      level = 0
      phase = CLEANING
      timer = 0
    end
  elseif phase == CLEANING then
    code = 6
    timer = timer + 1
    if timer >= 5 then
      batches = batches + 1
      phase = IDLE
    end
  else -- FAULT
    code = 7
    faults = faults + 1
    if noise % 8 == 0 then
      phase = IDLE
    end
  end

  local m = noise % 16
  local weight
  if m >= 0 and m <= 3 then
    weight = 1
  elseif m == 4 or m == 6 or m == 8 then
    weight = 2
  elseif m == 5 or m == 7 then
    weight = 3
  elseif m >= 9 and m <= 12 then
    weight = 5
  else
    weight = 7
  end

  checksum = (checksum * 3 + code * 10 + weight) % 1000003
end
print(checksum)
