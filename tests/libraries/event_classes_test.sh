#!/bin/sh
# TC_EVENTS and TC_EVENT_CLASSES from a TwinCAT project's event classes
# (decision 0372): the .tsproj's class (not the .tmc's repetition of it) and
# the .tmc's own class become the globals, events carry their class' texts
# with the arguments in {n}, in the log lines, sEventText, sEventClassName,
# RequestEventText and FB_RequestEventText. A folder whose sources do not
# name the lists gets none; a broken .tmc adds nothing; a POU named alone
# gets help instead.
#   event_classes_test.sh STRUN TEST_SOURCE_DIR
set -eu
strun=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; echo "--- stderr"; cat "$tmp/err" 2>/dev/null; exit 1; }
"$strun" run --virtual --cycles 2 --dump "$src/event_classes" > "$tmp/dump.json" 2> "$tmp/err" || fail "the project did not run"
for expect in '"startedId": *1,' '"overheatId": *7,' '"overheatSeverity": *"Error"' '"valveSeverity": *"Critical"' \
    '"msgText": *"Pump P1 started at 1450 rpm"' '"className": *"Pump station"' \
    "\"alarmText\": *\"Pump overheated: it's 95.5 \\\$C\"" '"requested": *"Pump P2 started at {1} rpm"' \
    '"valveText": *"Valve stuck"' '"classIsPump": *true' '"raised": *true' '"Data1": *287454020' '"Data1": *168496141'; do
    grep -q "$expect" "$tmp/dump.json" || fail "dump lacks $expect"
done
grep -q '^ADSLOG T#[0-9a-z#]* MainTask hint: event 1 message: Pump P1 started at 1450 rpm args P1, 1450$' "$tmp/err" || fail "message line"
grep -q "^ADSLOG T#[0-9a-z#]* MainTask error: event 7 alarm raised: Pump overheated: it's 95.5 \\\$C args 95.5\$" "$tmp/err" || fail "alarm line"
grep -q '^ADSLOG T#[0-9a-z#]* MainTask warning: event 0 message: Valve stuck$' "$tmp/err" || fail "SendMessageEx line"
if grep -q 'not read' "$tmp/dump.json" "$tmp/err"; then fail "the .tmc's repetition of the class was read"; fi
# The same folder whose code does not name TC_EVENTS: no lists are made.
cp -r "$src/event_classes" "$tmp/plain"
cat > "$tmp/plain/Plant/POUs/MAIN.TcPOU" <<'XML'
<?xml version="1.0" encoding="utf-8"?>
<TcPlcObject Version="1.1.0.1"><POU Name="MAIN" Id="{7a1c2b44-0d6e-4f1a-9c55-1e2d3c4b5a69}">
<Declaration><![CDATA[PROGRAM MAIN
VAR n : INT; END_VAR
]]></Declaration><Implementation><ST><![CDATA[n := n + 1;]]></ST></Implementation></POU></TcPlcObject>
XML
"$strun" run --virtual --cycles 1 --dump "$tmp/plain" > "$tmp/plain.json" 2> "$tmp/err" || fail "the plain project did not run"
if grep -q 'TC_EVENTS\|PumpEvents' "$tmp/plain.json"; then fail "lists made for a project that does not name them"; fi
# A .tmc that is not XML, or whose classes lack a GUID or an Id, adds nothing and breaks nothing.
cp -r "$src/event_classes" "$tmp/broken"
printf '<TcModuleClass><DataTypes><DataType><Name GUID="{0A0B' > "$tmp/broken/Plant/Plant.tmc"
set +e
"$strun" check "$tmp/broken" > "$tmp/err" 2>&1
rc=$?
set -e
[ "$rc" = 1 ] || fail "a broken .tmc: exit $rc, expected 1 (the program names ValveEvents)"
grep -q "ValveEvents" "$tmp/err" || fail "no error for the class the broken .tmc held"
if grep -q "PumpEvents" "$tmp/err"; then fail "the .tsproj's class was lost"; fi
# Without the folder (one POU named alone) TC_EVENTS is unknown, and the help says where it comes from.
if "$strun" check "$src/event_classes/Plant/POUs/MAIN.TcPOU" > "$tmp/err" 2>&1; then fail "TC_EVENTS without event classes compiled"; fi
grep -q "help: 'TC_EVENTS' is generated from the project's event classes" "$tmp/err" || fail "no help for TC_EVENTS"
echo PASS
