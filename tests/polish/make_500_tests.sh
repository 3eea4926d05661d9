#!/bin/sh
# Writes a project of 500 tests (50 suites of 10 tests, each test a loop of
# LOOP statements) to FILE: the project docs/testing.md measures -j on.
# Run it with --stmt-cost 1ns (each suite call stays far below the 200 ms
# watchdog). Not a ctest (no timed tests in CI). usage: make_500_tests.sh FILE [LOOP]
out=$1
loop=${2:-200000}
{
    s=1
    while [ $s -le 50 ]; do
        echo "FUNCTION_BLOCK FB_Suite$s EXTENDS FB_TestSuite"
        echo "VAR i : DINT; sum : DINT; END_VAR"
        t=1
        while [ $t -le 10 ]; do
            echo "TEST('Test$t'); sum := 0; FOR i := 1 TO $loop DO sum := sum + 1; END_FOR"
            echo "AssertEquals_DINT(Expected := $loop, Actual := sum, Message := 'sum'); TEST_FINISHED();"
            t=$((t + 1))
        done
        echo "END_FUNCTION_BLOCK"
        s=$((s + 1))
    done
} > "$out"
