#!/bin/sh
# Tests that never ran (a test before them loops) are in the JUnit report
# too, failing with `not run` (issue 29).
# usage: not_run_in_junit.sh STRUN SUITE.st
strun=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$strun" test --junit "$tmp/r.xml" "$2" > /dev/null
[ $? = 1 ] || { echo "expected exit 1"; exit 1; }
grep -q '<testsuites name="strun" tests="4" failures="3"' "$tmp/r.xml" || { echo "JUnit counts wrong:"; cat "$tmp/r.xml"; exit 1; }
[ "$(grep -c 'type="NOT_RUN"' "$tmp/r.xml")" = 2 ] || { echo "expected two NOT_RUN failures:"; cat "$tmp/r.xml"; exit 1; }
echo ok
