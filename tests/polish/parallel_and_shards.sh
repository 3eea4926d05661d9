#!/bin/sh
# strun test -j N and --shard K/N (issue 29): the verdicts of a parallel run
# are those of the serial run, in the same (declaration) order; the shards
# together run every suite once; the JUnit report of -j holds every test.
# usage: parallel_and_shards.sh STRUN
strun=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# Five suites of two tests each; one failing test in the third suite.
{
    for s in 1 2 3 4 5; do
        echo "FUNCTION_BLOCK FB_S$s EXTENDS FB_TestSuite"
        echo "VAR i : INT; END_VAR"
        echo "TEST('A$s'); FOR i := 1 TO 50 DO ; END_FOR AssertEquals_INT(Expected := 51, Actual := i, Message := 'loop'); TEST_FINISHED();"
        if [ $s = 3 ]; then
            echo "TEST('B$s'); AssertTrue(FALSE, 'fails'); TEST_FINISHED();"
        else
            echo "TEST('B$s'); AssertTrue(TRUE, 'ok'); TEST_FINISHED();"
        fi
        echo "END_FUNCTION_BLOCK"
    done
    echo "PROGRAM PRG_TEST"
    echo "VAR s1 : FB_S1; s2 : FB_S2; s3 : FB_S3; s4 : FB_S4; s5 : FB_S5; END_VAR"
    echo "TcUnit.RUN();"
    echo "END_PROGRAM"
} > "$tmp/suites.st"
fail() { echo "$1"; exit 1; }
"$strun" test "$tmp/suites.st" > "$tmp/serial.out"
[ $? = 1 ] || fail "serial run: expected exit 1 (one failing test)"
grep -q '^9 passed, 1 failed$' "$tmp/serial.out" || fail "serial summary wrong: $(cat "$tmp/serial.out")"
for j in 2 3 5 9 0; do
    "$strun" test -j $j --junit "$tmp/j$j.xml" "$tmp/suites.st" > "$tmp/j$j.out"
    [ $? = 1 ] || fail "-j $j: expected exit 1"
    cmp -s "$tmp/serial.out" "$tmp/j$j.out" || { diff "$tmp/serial.out" "$tmp/j$j.out"; fail "-j $j: output differs from the serial run"; }
    grep -q '<testsuites name="strun" tests="10" failures="1"' "$tmp/j$j.xml" || fail "-j $j: merged JUnit counts wrong"
    [ "$(grep -c '<testcase ' "$tmp/j$j.xml")" = 10 ] || fail "-j $j: merged JUnit does not hold 10 test cases"
    [ "$(grep -c '<testsuite id=' "$tmp/j$j.xml")" = 5 ] || fail "-j $j: merged JUnit does not hold 5 suites"
done
# Shards: together exactly the serial verdicts, in order; each alone a summary of its own.
: > "$tmp/shards.out"
for k in 1 2 3; do
    "$strun" test --shard $k/3 "$tmp/suites.st" > "$tmp/shard$k.out"
    grep -v 'passed, ' "$tmp/shard$k.out" >> "$tmp/shards.out"
done
grep -v 'passed, ' "$tmp/serial.out" > "$tmp/serial.lines"
cmp -s "$tmp/serial.lines" "$tmp/shards.out" || { diff "$tmp/serial.lines" "$tmp/shards.out"; fail "shards 1..3/3 together differ from the serial run"; }
# Slices of 5 suites in 3: floor(i*3/5) gives s1 s2 | s3 s4 | s5; the failing test is in 2/3.
"$strun" test --shard 2/3 "$tmp/suites.st" > /dev/null
[ $? = 1 ] || fail "--shard 2/3 holds the failing test: expected exit 1"
"$strun" test --shard 1/3 "$tmp/suites.st" > /dev/null || fail "--shard 1/3 passes: expected exit 0"
# More shards than suites: an empty shard passes with a note (the others run the suites).
"$strun" test --shard 7/9 "$tmp/suites.st" > /dev/null 2> "$tmp/empty.err"; rc=$?
[ $rc = 0 ] && grep -q 'holds no suite' "$tmp/empty.err" || fail "--shard 7/9: expected exit 0 and a note, got $rc: $(cat "$tmp/empty.err")"
"$strun" test --shard 4/3 "$tmp/suites.st" > /dev/null 2>&1
[ $? = 2 ] || fail "--shard 4/3: expected exit 2"
"$strun" test --list --shard 3/3 "$tmp/suites.st" > "$tmp/list.out"
[ "$(cat "$tmp/list.out" | tr '\n' ' ')" = "s5.A5 s5.B5 " ] || fail "--list --shard 3/3: $(cat "$tmp/list.out")"
echo ok
