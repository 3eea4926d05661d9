#!/bin/bash
# Issue 30, the smaller items through the CLI: a JUnit report that always
# parses (bytes that are not UTF-8, no negative time), the tests after one
# that fails with CALL_DEPTH every cycle, a stimulus CSV with a UTF-8 BOM,
# TwinCAT CDATA with CR-only line ends, and --start at the calendar's edges.
#   inputs_test.sh STRUN TESTDIR
set -u
STRUN=$1
HERE=$2
WORK=$(mktemp -d /tmp/strun-inputs-XXXXXX)
trap 'rm -rf "$WORK"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# JUnit: well-formed whatever the bytes; no negative time; CALL_DEPTH does not starve the suite.
timeout 60 "$STRUN" test --junit "$WORK/report.xml" "$HERE/junit_suite.st" >"$WORK/out" 2>"$WORK/err"
status=$?
[ $status = 1 ] || fail "strun test: exit $status: $(cat "$WORK/out" "$WORK/err")"
python3 - "$WORK/report.xml" <<'PY' || fail "the JUnit report is not well-formed XML: $(head -c 3000 "$WORK/report.xml")"
import sys, xml.etree.ElementTree as ET
root = ET.parse(sys.argv[1]).getroot()
times = [float(e.get("time")) for e in root.iter() if e.get("time") is not None]
assert all(t >= 0 for t in times), times
names = [c.get("name") for c in root.iter("testcase")]
assert "caf\ufffd" in names, names
assert "AfterDeep" in names and "AfterDeepFails" in names, names
PY
grep -q '^PASS FB_Depth.AfterDeep$\|^PASS depth.AfterDeep$' "$WORK/out" || fail "the test after a CALL_DEPTH test did not run: $(cat "$WORK/out")"
grep -q '^FAIL [A-Za-z_]*\.AfterDeepFails: ' "$WORK/out" || fail "a later failing test was not counted: $(cat "$WORK/out")"
grep -q 'TooDeep: .*CALL_DEPTH' "$WORK/out" || fail "the CALL_DEPTH test: $(cat "$WORK/out")"
grep -q 'Endless: .*WATCHDOG' "$WORK/out" || fail "the watchdog test: $(cat "$WORK/out")"
grep -q '^1 passed, 4 failed$' "$WORK/out" || fail "the counts: $(cat "$WORK/out")"

# A stimulus CSV saved with a UTF-8 byte-order mark, header line first.
printf 'PROGRAM Main VAR x : INT; END_VAR END_PROGRAM\n' > "$WORK/main.st"
printf '\xef\xbb\xbfTIME,NAME,VALUE\n0ms,Main.x,5\n' > "$WORK/bom.csv"
out=$("$STRUN" run --virtual --cycles 1 --dump --stimulus "$WORK/bom.csv" "$WORK/main.st" 2>"$WORK/err") || fail "a CSV with a BOM: $(cat "$WORK/err")"
grep -q '"x": 5' <<<"$out" || fail "the BOM CSV was not applied: $out"
printf '\xef\xbb\xbf0ms,Main.x,7\n' > "$WORK/bom2.csv"
out=$("$STRUN" run --virtual --cycles 1 --dump --stimulus "$WORK/bom2.csv" "$WORK/main.st" 2>"$WORK/err") || fail "a CSV with a BOM and no header: $(cat "$WORK/err")"
grep -q '"x": 7' <<<"$out" || fail "the BOM CSV without header was not applied: $out"

# TwinCAT CDATA with CR-only line ends: the error is on line 11 of the file.
printf '<?xml version="1.0" encoding="utf-8"?>\r<TcPlcObject Version="1.1.0.1">\r  <POU Name="MAIN" Id="{00000000-0000-0000-0000-000000000001}" SpecialFunc="None">\r    <Declaration><![CDATA[PROGRAM MAIN\rVAR\r    x : INT;\rEND_VAR\r]]></Declaration>\r    <Implementation>\r      <ST><![CDATA[x := x + 1;\ry := 2;]]></ST>\r    </Implementation>\r  </POU>\r</TcPlcObject>\r' > "$WORK/MAIN.TcPOU"
"$STRUN" check "$WORK/MAIN.TcPOU" >/dev/null 2>"$WORK/err" && fail "the undeclared y was not reported"
grep -q "MAIN.TcPOU:11:1: error: undeclared identifier 'y'" "$WORK/err" || fail "CR-only line ends: $(cat "$WORK/err")"

# --start at the edges of the 64-bit nanosecond calendar: refused clearly, never wrapped.
for start in DT#1677-01-01-00:00:00 DT#1969-12-31-23:59:59 DT#2116-01-01-00:00:01 DT#2262-04-11-23:47:16 DT#2263-01-01-00:00:00; do
    "$STRUN" run --virtual --cycles 1 --start "$start" "$WORK/main.st" >/dev/null 2>"$WORK/err"
    status=$?
    [ $status = 2 ] || fail "--start $start: exit $status: $(cat "$WORK/err")"
    grep -q -- "--start" "$WORK/err" || fail "--start $start: $(cat "$WORK/err")"
done
"$STRUN" run --virtual --cycles 1 --start DT#2116-01-01-00:00:00 "$WORK/main.st" 2>"$WORK/err" || fail "the latest --start: $(cat "$WORK/err")"

# --vcd records at most 100 000 variables; --watch picks elements past that bound.
printf 'PROGRAM Main VAR a : ARRAY[0..199999] OF BYTE; END_VAR a[199999] := a[199999] + 1; END_PROGRAM\n' > "$WORK/big.st"
"$STRUN" run --virtual --cycles 2 --quiet --vcd "$WORK/all.vcd" "$WORK/big.st" 2>"$WORK/err" || fail "--vcd of a big array: $(cat "$WORK/err")"
grep -q "more than 100000 variables to record" "$WORK/err" || fail "no --vcd bound warning: $(cat "$WORK/err")"
[ "$(grep -c '^\$var wire 8 ' "$WORK/all.vcd")" = 100000 ] || fail "not 100000 signals recorded"
"$STRUN" run --virtual --cycles 2 --quiet --vcd "$WORK/one.vcd" --watch 'Main.a[199999]' "$WORK/big.st" 2>"$WORK/err" || fail "--watch an element"
[ -s "$WORK/err" ] && fail "--watch of one element warned: $(cat "$WORK/err")"
grep -q ' a(199999) \$end' "$WORK/one.vcd" || fail "--watch did not pick the element: $(head -20 "$WORK/one.vcd")"

# Time-event tasks whose AT is at the ends of the 64-bit calendar: a DAILY one
# from 1677 fires every day of the run (its occurrences were computed with
# overflowing arithmetic: never), one in 2262 never within the run.
cat > "$WORK/events.st" <<'ST'
PROGRAM Count
VAR n : INT; END_VAR
n := n + 1;
END_PROGRAM
CONFIGURATION Plant
    RESOURCE Cpu ON PLC
        TASK Old (AT := LDT#1677-09-22-00:00:01, REPEAT := DAILY, PRIORITY := 5);
        TASK OldMonth (AT := LDT#1677-09-22-00:00:01, REPEAT := MONTHLY, PRIORITY := 6);
        TASK Late (AT := LDT#2262-04-10-23:47:16, REPEAT := HOURLY, PRIORITY := 7);
        PROGRAM D WITH Old : Count;
        PROGRAM M WITH OldMonth : Count;
        PROGRAM L WITH Late : Count;
    END_RESOURCE
END_CONFIGURATION
ST
out=$("$STRUN" run --virtual --start DT#2026-01-01-00:00:00 --for 3d --dump "$WORK/events.st" 2>"$WORK/err") || fail "time events at the calendar's ends: $(cat "$WORK/err")"
[ "$(tr -d ' \n' <<<"$out" | grep -o '"D":{"n":[0-9]*}')" = '"D":{"n":3}' ] || fail "DAILY from 1677: $out"
[ "$(tr -d ' \n' <<<"$out" | grep -o '"M":{"n":[0-9]*}')" = '"M":{"n":0}' ] || fail "MONTHLY from 1677: $out"
[ "$(tr -d ' \n' <<<"$out" | grep -o '"L":{"n":[0-9]*}')" = '"L":{"n":0}' ] || fail "HOURLY in 2262: $out"

# STRING_TO_DCTIME64 at the end of the 64-bit calendar: the exact ULINT, no wrap; before 2000: 0.
cat > "$WORK/dc.st" <<'ST'
PROGRAM Main
VAR late, latest, early : ULINT; END_VAR
late := STRING_TO_DCTIME64('2262-04-11-23:47:16.854775807');
latest := STRING_TO_DCTIME64('2262-04-11-23:47:16.999999999');
early := STRING_TO_DCTIME64('1677-09-21-00:12:44.000000001');
END_PROGRAM
ST
out=$("$STRUN" run --virtual --cycles 1 --dump "$WORK/dc.st" 2>"$WORK/err") || fail "STRING_TO_DCTIME64: $(cat "$WORK/err")"
grep -q '"late": 8276687236854775807' <<<"$out" || fail "STRING_TO_DCTIME64 late in 2262: $out"
grep -q '"latest": 8276687236999999999' <<<"$out" || fail "STRING_TO_DCTIME64 past INT64_MAX ns: $out"
grep -q '"early": 0' <<<"$out" || fail "STRING_TO_DCTIME64 in 1677: $out"
echo "PASS"
