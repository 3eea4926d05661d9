#!/bin/sh
# With --diagnostics-format json every stderr line of a run is a JSON object,
# the end-of-run summary included (issue 29).
# usage: json_summary.sh STRUN
strun=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf 'PROGRAM Main\nVAR x : INT; d : INT; END_VAR\nx := x + 1;\nx := x / d;\nEND_PROGRAM\n' > "$tmp/m.st"
"$strun" run --virtual --cycles 2 --diagnostics-format json "$tmp/m.st" 2> "$tmp/err" || { echo "run failed"; cat "$tmp/err"; exit 1; }
if grep -v '^{.*}$' "$tmp/err" | grep -q .; then echo "a stderr line is not a JSON object:"; cat "$tmp/err"; exit 1; fi
[ "$(grep -c '^{"summary":{"state":"RUN","time":"T#' "$tmp/err")" = 1 ] || { echo "no JSON summary line:"; cat "$tmp/err"; exit 1; }
grep '^{"summary"' "$tmp/err" | grep -q '"name":"MainTask".*"cycles":2' || { echo "summary lacks the task:"; cat "$tmp/err"; exit 1; }
grep '^{"summary"' "$tmp/err" | grep -q '"code":"DIV_BY_ZERO"' || { echo "summary lacks the diagnostic:"; cat "$tmp/err"; exit 1; }
echo ok
