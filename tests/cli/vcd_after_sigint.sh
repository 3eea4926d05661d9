#!/bin/sh
# A run on the real clock stopped by Ctrl-C (SIGINT) still leaves a complete
# VCD: the header, the task signal back to 0, and a final time stamp.
# usage: vcd_after_sigint.sh STRUN PROGRAM
strun=$1
program=$2
vcd=$(mktemp)
trap 'rm -f "$vcd"' EXIT
"$strun" run --vcd "$vcd" --quiet "$program" &
pid=$!
sleep 0.5
kill -INT "$pid"
wait "$pid"
rc=$?
[ "$rc" -eq 0 ] || { echo "exit status $rc after SIGINT, expected 0"; exit 1; }
grep -q '^\$enddefinitions \$end$' "$vcd" || { echo "no \$enddefinitions"; exit 1; }
grep -q '^1!$' "$vcd" || { echo "the task never ran"; exit 1; }
[ "$(grep '^[01]!$' "$vcd" | tail -n 1)" = "0!" ] || { echo "the task signal does not end at 0:"; tail -n 3 "$vcd"; exit 1; }
grep -q '^#[1-9][0-9]*$' "$vcd" || { echo "no time stamp after 0:"; tail -n 3 "$vcd"; exit 1; }
echo "ok"
