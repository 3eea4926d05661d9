#!/bin/sh
# The shipped examples compile without a single warning (issue 29): each
# programs/*.st with the --target its header names, and the test folder.
# usage: examples_warning_clean.sh STRUN PROGRAMS_DIR
strun=$1
dir=$2
status=0
for f in "$dir"/*.st "$dir"/traffic_light_tests; do
    target=$(grep -o -m1 -- '--target [a-z0-9]*' "$f" 2>/dev/null | head -n1 | cut -d' ' -f2)
    [ -d "$f" ] && target=
    out=$("$strun" check --color never ${target:+--target "$target"} "$f" 2>&1)
    if [ -n "$out" ]; then
        echo "$f${target:+ (--target $target)} is not warning-clean:"
        echo "$out"
        status=1
    fi
done
[ $status = 0 ] && echo ok
exit $status
