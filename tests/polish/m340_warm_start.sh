#!/bin/sh
# M340 (seed 002): "The maximum and minimum times are taken from the times
# measured since the last cold restart" (decision 0296). Run 1 makes long
# MAST cycles (about 5 ms), run 2 (a warm start from the same --retain file)
# short ones (about 1 ms): its %SW31 still shows run 1's maximum and %SW32
# its own minimum. Run 3 with --cold starts the measurement again.
# usage: m340_warm_start.sh STRUN
strun=$1
dir=$(mktemp -d) || exit 1
trap 'rm -rf "$dir"' EXIT
cat > "$dir/plant.st" <<'ST'
PROGRAM Master
VAR
    work : INT := 40;
    i : INT;
    maxMs : WORD;
    minMs : WORD;
END_VAR
FOR i := 1 TO work DO
    ;
END_FOR
maxMs := %SW31;
minMs := %SW32;
END_PROGRAM
CONFIGURATION Plant
    TASK MAST (INTERVAL := T#50ms);
    PROGRAM M WITH MAST : Master;
END_CONFIGURATION
ST
run() {
    "$strun" run --target m340 --virtual --stmt-cost 100us --cycles 3 --dump --retain "$dir/plc.retain" "$@" "$dir/plant.st" 2>"$dir/err"
}
value() { printf '%s\n' "$1" | grep "\"$2\":" | head -1 | tr -dc '0-9'; }
out=$(run) || { echo "run 1 failed: $(cat "$dir/err")"; exit 1; }
max1=$(value "$out" maxMs)
[ "$max1" -ge 4 ] || { echo "run 1: expected a maximum of at least 4 ms, got '$max1'"; exit 1; }
out=$(run --set M.work=5) || { echo "run 2 failed: $(cat "$dir/err")"; exit 1; }
max2=$(value "$out" maxMs); min2=$(value "$out" minMs)
[ "$max2" = "$max1" ] || { echo "warm start: %SW31 = $max2, expected run 1's $max1"; exit 1; }
[ "$min2" -lt "$max1" ] || { echo "warm start: %SW32 = $min2, expected this run's short cycles (< $max1)"; exit 1; }
grep -q 'warning' "$dir/err" && { echo "unexpected warning: $(cat "$dir/err")"; exit 1; }
out=$(run --cold --set M.work=5) || { echo "run 3 failed: $(cat "$dir/err")"; exit 1; }
max3=$(value "$out" maxMs)
[ "$max3" -lt "$max1" ] || { echo "cold start: %SW31 = $max3, expected the measurement to start again (< $max1)"; exit 1; }
echo ok
