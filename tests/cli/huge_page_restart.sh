#!/bin/sh
# Decision 0494: `strun run|check|test` of 256 KiB of sources or more
# restarts itself once with GLIBC_TUNABLES=glibc.malloc.hugetlb=1 (the
# compile's heap in transparent huge pages); smaller inputs, other commands
# and a GLIBC_TUNABLES the user set do not. The restart is seen in
# /proc/PID/environ of a run on the real clock; its results are those of a
# run without it.
# usage: huge_page_restart.sh STRUN [sanitized]
# (sanitized: a sanitizer build, whose allocator is not glibc's, never restarts)
strun=$1
expect=glibc.malloc.hugetlb=1
[ "${2:-}" = sanitized ] && expect=none
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# A program of about 300 KiB, with one type error near its end.
big=$dir/big.st
{
    echo "PROGRAM Main"
    echo "VAR x : DINT; flag : BOOL; END_VAR"
    i=0
    while [ $i -lt 4000 ]; do
        echo "x := x + 1; (* statement $i, padded so that the file is large ............ *)"
        i=$((i + 1))
    done
    echo "flag := x;"
    echo "END_PROGRAM"
} >"$big"
[ "$(wc -c <"$big")" -ge 262144 ] || fail "the generated program is under 256 KiB"
small=$dir/small.st
printf 'PROGRAM Main\nVAR x : DINT; END_VAR\nx := x + 1;\nEND_PROGRAM\n' >"$small"
# The same program in many small files: a directory counts its files.
mkdir "$dir/project"
i=0
while [ $i -lt 40 ]; do
    { echo "FUNCTION F$i : DINT"; echo "VAR_INPUT a : DINT; END_VAR"
      j=0; while [ $j -lt 100 ]; do echo "F$i := F$i + a; (* padding padding padding padding padding padding *)"; j=$((j + 1)); done
      echo "END_FUNCTION"; } >"$dir/project/f$i.st"
    i=$((i + 1))
done
cp "$small" "$dir/project/main.st"

# Ends a background run: SIGTERM (a background job of a non-interactive
# shell ignores SIGINT until strun installs its handler, which a run still
# compiling has not), SIGKILL if it is still there after a second.
stop() {
    kill -TERM "$1" 2>/dev/null
    n=0
    while kill -0 "$1" 2>/dev/null && [ $n -lt 20 ]; do sleep 0.05; n=$((n + 1)); done
    kill -KILL "$1" 2>/dev/null
    wait "$1" 2>/dev/null
}

# Prints the GLIBC_TUNABLES of a real-clock run of the given inputs ("none"
# when it has none), read from /proc while it runs.
tunables_of_run() {
    env -u GLIBC_TUNABLES "$strun" run --quiet "$@" >/dev/null 2>&1 &
    pid=$!
    seen=none
    k=0
    while [ $k -lt 100 ]; do
        if [ -r "/proc/$pid/environ" ]; then
            t=$(tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | sed -n 's/^GLIBC_TUNABLES=//p')
            if [ -n "$t" ]; then seen=$t; break; fi
            # Running with its arguments parsed and no tunables: no restart came.
            if [ $k -ge 30 ]; then break; fi
        fi
        sleep 0.05
        k=$((k + 1))
    done
    stop "$pid"
    echo "$seen"
}

[ -r /proc/self/environ ] || { echo "no /proc: skipped"; exit 0; }
bigfix=$dir/big_ok.st
sed 's/^flag := x;$/flag := x > 0;/' "$big" >"$bigfix"
[ "$(tunables_of_run "$bigfix")" = "$expect" ] || fail "a run of 300 KiB: tunables not '$expect'"
[ "$(tunables_of_run "$dir/project")" = "$expect" ] || fail "a run of a 300 KiB directory: tunables not '$expect'"
[ "$(tunables_of_run "$small")" = "none" ] || fail "a run of a one-line program restarted"

# The user's own GLIBC_TUNABLES is kept as it is.
GLIBC_TUNABLES=glibc.malloc.check=0 "$strun" run --quiet "$bigfix" >/dev/null 2>&1 &
pid=$!
sleep 0.5
t=$(tr '\0' '\n' <"/proc/$pid/environ" 2>/dev/null | sed -n 's/^GLIBC_TUNABLES=//p')
stop "$pid"
[ "$t" = "glibc.malloc.check=0" ] || fail "the user's GLIBC_TUNABLES became '$t'"

# Restarted or not, the same diagnostics and exit status.
env -u GLIBC_TUNABLES "$strun" check "$big" >"$dir/restarted.out" 2>&1
rc1=$?
GLIBC_TUNABLES= "$strun" check "$big" >"$dir/plain.out" 2>&1
rc2=$?
[ $rc1 -eq 1 ] && [ $rc2 -eq 1 ] || fail "check of the program with an error: exit $rc1 and $rc2, expected 1"
cmp -s "$dir/restarted.out" "$dir/plain.out" || { diff "$dir/restarted.out" "$dir/plain.out"; fail "the diagnostics differ"; }
grep -q "big.st:4003:" "$dir/restarted.out" || { cat "$dir/restarted.out"; fail "the type error is not reported at line 4003"; }
env -u GLIBC_TUNABLES "$strun" run --virtual --cycles 2 --dump "$bigfix" >"$dir/restarted.json" 2>&1 || fail "the restarted run failed"
GLIBC_TUNABLES= "$strun" run --virtual --cycles 2 --dump "$bigfix" >"$dir/plain.json" 2>&1 || fail "the plain run failed"
cmp -s "$dir/restarted.json" "$dir/plain.json" || fail "the dumps differ"
grep -q '"x": 8000' "$dir/restarted.json" || { head -c 600 "$dir/restarted.json"; fail "x is not 8000 after two cycles"; }
echo "ok"
