-- Lua twin of case_machine.st: a tokenizer state machine over a
-- pseudo-random symbol stream (6M symbols); CASE as if/elseif chains, the
-- enumeration as integer constants.
local IDLE, IN_NUMBER, IN_NAME, IN_STRING, ESCAPE, IN_COMMENT, OPERATOR, FAILED = 0, 1, 2, 3, 4, 5, 6, 7
local seed, st = 99, IDLE
local numbers, names, strings, ops, errors, value = 0, 0, 0, 0, 0, 0
for _ = 1, 6000000 do
  seed = (seed * 1103 + 12345) % 65536
  local sym = seed % 64
  local cls
  if sym <= 9 then cls = 1
  elseif sym <= 35 then cls = 2
  elseif sym == 36 then cls = 3
  elseif sym == 37 then cls = 4
  elseif sym == 38 or sym == 39 then cls = 5
  elseif sym <= 47 then cls = 6
  elseif sym <= 59 then cls = 0
  else cls = 7 end
  if st == IDLE then
    if cls == 1 then st = IN_NUMBER; value = sym
    elseif cls == 2 then st = IN_NAME
    elseif cls == 3 then st = IN_STRING
    elseif cls == 5 then st = IN_COMMENT
    elseif cls == 6 then st = OPERATOR
    elseif cls == 4 then st = FAILED end
  elseif st == IN_NUMBER then
    if cls == 1 then value = (value * 10 + sym) % 10007
    elseif cls == 2 or cls == 3 or cls == 4 then st = FAILED
    else numbers = numbers + 1; st = IDLE end
  elseif st == IN_NAME then
    if cls == 1 or cls == 2 then
    elseif cls == 6 then names = names + 1; st = OPERATOR
    else names = names + 1; st = IDLE end
  elseif st == IN_STRING then
    if cls == 3 then strings = strings + 1; st = IDLE
    elseif cls == 4 then st = ESCAPE
    elseif cls == 7 then st = FAILED end
  elseif st == ESCAPE then
    st = IN_STRING
  elseif st == IN_COMMENT then
    if cls == 7 then st = IDLE end
  elseif st == OPERATOR then
    ops = ops + 1
    if cls == 1 then st = IN_NUMBER; value = sym
    elseif cls == 2 then st = IN_NAME
    else st = IDLE end
  elseif st == FAILED then
    errors = errors + 1
    if cls == 0 or cls == 7 then st = IDLE end
  end
end
print(numbers * 7 + names * 5 + strings * 3 + ops * 2 + errors + value)
