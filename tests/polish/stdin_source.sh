#!/bin/sh
# `-` reads the source from standard input (issue 29): it runs, its messages
# name <stdin>, and a second `-` is a command-line error.
# usage: stdin_source.sh STRUN
strun=$1
prog='PROGRAM Main
VAR x : INT; END_VAR
x := x + 2;
END_PROGRAM'
out=$(printf '%s\n' "$prog" | "$strun" run --virtual --cycles 3 --dump -) || { echo "run - failed"; exit 1; }
echo "$out" | grep -q '"x": 6' || { echo "expected x = 6 after 3 cycles, got: $out"; exit 1; }
err=$(printf 'PROGRAM Main\nx := 1;\nEND_PROGRAM\n' | "$strun" check --color never - 2>&1)
[ $? = 1 ] || { echo "check of a wrong program from stdin did not exit 1"; exit 1; }
echo "$err" | grep -q '^<stdin>:2:1: error: undeclared identifier' || { echo "message does not name <stdin>: $err"; exit 1; }
printf '%s\n' "$prog" | "$strun" check - - 2>/dev/null
[ $? = 2 ] || { echo "two '-' did not exit 2"; exit 1; }
echo ok
