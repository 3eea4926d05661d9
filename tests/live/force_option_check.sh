#!/bin/sh
# --force without a server: the value holds against the program's own
# writes; the summary and --dump list the forces; a force --set would
# refuse exits 2 with the --set message. Usage: force_option_check.sh STRUN PROGRAM
set -u
STRUN="$1"; PROG="$2"
fail() { echo "FAIL: $*"; exit 1; }

out=$("$STRUN" run --virtual --cycles 5 --force Main.x=7 --force '%QX0.1=TRUE' --force "main.name='held'" --dump "$PROG") || fail "run: exit $?"
echo "$out" | python3 -c '
import json, sys
d = json.load(sys.stdin)
assert d["forces"] == {"Main.x": 7, "%QX0.1": True, "Main.name": "held"}, d["forces"]
m = d["programs"]["Main"]
assert m["x"] == 7 and m["mirror"] == 8, (m["x"], m["mirror"])
assert m["out"] is True and m["name"] == "held", m
assert m["counter"] == 5
' || fail "dump: $out"

err=$("$STRUN" run --virtual --cycles 3 --force Main.x=7 "$PROG" 2>&1 >/dev/null) || fail "summary run: exit $?"
echo "$err" | grep -q "^  forces: Main.x = 7$" || fail "summary: $err"

plain=$("$STRUN" run --virtual --cycles 3 --dump "$PROG") || fail "plain run"
echo "$plain" | python3 -c 'import json,sys; assert json.load(sys.stdin)["forces"] == {}' || fail "no forces: $plain"

for bad in "Main.small=300:does not fit SINT" "Main.nothing=1:no variable 'nothing'" "Main.x:expected NAME=VALUE" "%IX0.9=TRUE:bit number"; do
  arg=${bad%%:*}; want=${bad#*:}
  msg=$("$STRUN" run --virtual --cycles 1 --force "$arg" "$PROG" 2>&1); code=$?
  [ "$code" -eq 2 ] || fail "--force $arg: exit $code"
  echo "$msg" | grep -q -- "--force $arg: .*$want" || fail "--force $arg: $msg"
done
echo "ok   --force: held, listed in the summary and the dump; refused like --set"
