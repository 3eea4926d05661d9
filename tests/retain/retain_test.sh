#!/bin/bash
# --retain through the CLI: warm and cold start, a changed program, a damaged
# file, SIGTERM, and SIGKILL at random moments of a real-clock run (the file
# must always be complete and the counter must never go back).
#   retain_test.sh STRUN TESTDIR
set -u
STRUN=$1
HERE=$2
WORK=$(mktemp -d /tmp/strun-retain-XXXXXX)
trap 'rm -rf "$WORK"' EXIT
FILE=$WORK/plc.retain
fail() { echo "FAIL: $*"; exit 1; }
value() { # value NAME JSON: the first integer after "NAME":
    grep -o "\"$1\": -\?[0-9]*" <<<"$2" | head -1 | grep -o -- '-\?[0-9]*$'
}

# Warm start continues, --cold starts again, the file is rewritten either way.
out=$("$STRUN" run --virtual --cycles 3 --dump --retain "$FILE" "$HERE/counter.st") || fail "first run"
[ "$(value count "$out")" = 3 ] || fail "first run count: $out"
out=$("$STRUN" run --virtual --cycles 2 --dump --retain "$FILE" "$HERE/counter.st") || fail "warm run"
[ "$(value count "$out")" = 5 ] || fail "warm start did not restore count: $out"
[ "$(value gTotal "$out")" = 10 ] || fail "warm start did not restore gTotal: $out"
[ "$(value plain "$out")" = 2 ] || fail "a non-retained variable was restored: $out"
out=$("$STRUN" run --virtual --cycles 1 --dump --cold --retain "$FILE" "$HERE/counter.st") || fail "cold run"
[ "$(value count "$out")" = 1 ] || fail "--cold restored: $out"
out=$("$STRUN" run --virtual --cycles 1 --dump --retain "$FILE" "$HERE/counter.st") || fail "run after cold"
[ "$(value count "$out")" = 2 ] || fail "the cold run did not save: $out"

# A changed program: matching values restored, the rest warned about, never misread.
out=$("$STRUN" run --virtual --cycles 1 --dump --retain "$FILE" "$HERE/counter_changed.st" 2>"$WORK/err") || fail "changed run"
[ "$(value count "$out")" = 1 ] || fail "count changed type but was restored: $out"
[ "$(value gTotal "$out")" = 6 ] || fail "gTotal (unchanged) not restored: $out"
[ "$(value fresh "$out")" = 7 ] || fail "a new variable lost its initial value: $out"
grep -q "'Main.count' was LINT (8 bytes) and is now DINT (4 bytes)" "$WORK/err" || fail "no warning about the changed type: $(cat "$WORK/err")"
grep -q "'Main.history' is no longer a retained variable" "$WORK/err" || fail "no warning about the dropped variable: $(cat "$WORK/err")"

# A damaged file is a cold start with a warning, never misread bytes.
"$STRUN" run --virtual --cycles 4 --retain "$FILE" "$HERE/counter.st" 2>/dev/null || fail "run before damage"
head -c 60 "$FILE" > "$FILE.cut" && mv "$FILE.cut" "$FILE"
out=$("$STRUN" run --virtual --cycles 1 --dump --retain "$FILE" "$HERE/counter.st" 2>"$WORK/err") || fail "run on a damaged file"
[ "$(value count "$out")" = 1 ] || fail "a damaged file was restored: $out"
grep -q "is not a complete retain file" "$WORK/err" || fail "no warning about the damaged file"

# SIGTERM ends a real-clock run and saves.
rm -f "$FILE"
"$STRUN" run --retain "$FILE" --retain-every 1h "$HERE/counter.st" 2>/dev/null &
pid=$!
# Not before strun catches SIGTERM (a sanitizer build on a loaded machine can
# take longer than any fixed pause to get there), then a moment of cycles.
for _ in $(seq 1 600); do
    mask=$(awk '/^SigCgt:/ { print $2 }' /proc/$pid/status 2>/dev/null)
    [ -n "$mask" ] && [ $(( 0x$mask & 0x4000 )) -ne 0 ] && break
    sleep 0.05
done
sleep 0.5
kill -TERM $pid
wait $pid
[ -s "$FILE" ] || fail "SIGTERM did not save"
out=$("$STRUN" run --virtual --for 0 --dump --retain "$FILE" "$HERE/counter.st") || fail "run after SIGTERM"
[ "$(value count "$out")" -gt 0 ] || fail "SIGTERM saved no progress: $out"

# SIGKILL at random moments: the file is the previous or the new complete one.
rm -f "$FILE"
last=0
for round in $(seq 1 15); do
    "$STRUN" run --retain "$FILE" --retain-every 2ms "$HERE/counter.st" 2>"$WORK/err" &
    pid=$!
    sleep "0.$((RANDOM % 4 + 2))$((RANDOM % 10))"  # compiling takes about 0.1-0.2 s
    kill -KILL $pid
    wait $pid 2>/dev/null
    grep -q "not a complete retain file" "$WORK/err" && fail "round $round: the run started from a damaged file"
    [ -e "$FILE" ] || continue  # killed before the first save
    out=$("$STRUN" run --virtual --for 0 --dump --retain "$FILE" "$HERE/counter.st" 2>"$WORK/err") || fail "round $round: check run"
    grep -q "warning" "$WORK/err" && fail "round $round: $(cat "$WORK/err")"
    now=$(value count "$out")
    [ "$now" -ge "$last" ] || fail "round $round: count went back from $last to $now"
    last=$now
done
[ "$last" -gt 0 ] || fail "no round saved anything"
echo "PASS (count reached $last over the kill rounds)"
