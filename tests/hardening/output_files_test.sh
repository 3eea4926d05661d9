#!/bin/bash
# The files strun writes (issue 30, docs/cli.md "Files strun reads and
# writes", decision 0250): outputs that are not regular files, outputs that
# name an input, files that are not retain files, FIFOs as inputs, and
# write errors (a full device, a file size limit), each through the CLI.
#   output_files_test.sh STRUN TESTDIR
set -u
STRUN=$1
HERE=$2
WORK=$(mktemp -d /tmp/strun-outputs-XXXXXX)
trap 'rm -rf "$WORK"' EXIT
PROG=$WORK/counter.st
cp "$HERE/counter.st" "$PROG"
fail() { echo "FAIL: $*"; exit 1; }
# run EXPECTED_EXIT ARGS...: strun with a 20 s guard against a hang; stderr in $WORK/err.
run() {
    local expected=$1
    shift
    timeout 20 "$STRUN" "$@" >"$WORK/out" 2>"$WORK/err" </dev/null
    local status=$?
    [ $status = 124 ] && fail "hangs: strun $*"
    [ $status = "$expected" ] || fail "exit $status (expected $expected): strun $* -- $(cat "$WORK/err")"
}
same() { cmp -s "$1" "$2" || fail "$3"; }

# 1. An output path that exists and is not a regular file is refused before the run.
mkfifo "$WORK/fifo"
run 2 run --virtual --cycles 1 --retain "$WORK/fifo" "$PROG"
grep -q "not a regular file" "$WORK/err" || fail "--retain FIFO: $(cat "$WORK/err")"
[ -p "$WORK/fifo" ] || fail "--retain replaced the FIFO"
run 2 run --virtual --cycles 1 --vcd "$WORK/fifo" "$PROG"
grep -q "not a regular file" "$WORK/err" || fail "--vcd FIFO: $(cat "$WORK/err")"
mkdir "$WORK/dir"
run 2 run --virtual --cycles 1 --retain "$WORK/dir" "$PROG"
[ -d "$WORK/dir" ] || fail "--retain replaced a directory"
if mknod "$WORK/chardev" c 1 3 2>/dev/null; then  # the null device's numbers, in our own directory
    run 2 run --virtual --cycles 1 --retain "$WORK/chardev" "$PROG"
    [ -c "$WORK/chardev" ] || fail "--retain renamed a regular file over a character device"
    run 2 run --virtual --cycles 1 --vcd "$WORK/chardev" "$PROG"
fi
ln -s "$WORK/fifo" "$WORK/link-to-fifo"
run 2 run --virtual --cycles 1 --retain "$WORK/link-to-fifo" "$PROG"
[ -p "$WORK/fifo" ] && [ -L "$WORK/link-to-fifo" ] || fail "--retain through a link to a FIFO"

# 2. A FIFO as an input file is refused, never waited on.
run 2 check "$WORK/fifo"
run 2 run --virtual --cycles 1 --stimulus "$WORK/fifo" "$PROG"

# 3. A file that is not a retain file is not overwritten (unless --cold), and
#    no output names an input of the run.
cp "$PROG" "$WORK/copy.st"
run 2 run --virtual --cycles 1 --retain "$PROG" "$PROG"
grep -q "is an input of this run" "$WORK/err" || fail "--retain over the program: $(cat "$WORK/err")"
same "$PROG" "$WORK/copy.st" "--retain overwrote the program"
run 2 run --virtual --cycles 1 --vcd "$PROG" "$PROG"
same "$PROG" "$WORK/copy.st" "--vcd overwrote the program"
printf 'my notes\nline 2\n' > "$WORK/notes.txt"
cp "$WORK/notes.txt" "$WORK/notes.orig"
run 2 run --virtual --cycles 1 --retain "$WORK/notes.txt" "$PROG"
grep -q "is not a retain file" "$WORK/err" || fail "--retain over a text file: $(cat "$WORK/err")"
grep -q -- "--cold" "$WORK/err" || fail "the refusal does not name --cold: $(cat "$WORK/err")"
same "$WORK/notes.txt" "$WORK/notes.orig" "--retain overwrote a file that is not a retain file"
run 0 run --virtual --cycles 1 --cold --retain "$WORK/notes.txt" "$PROG"
head -1 "$WORK/notes.txt" | grep -q "^STRUN-RETAIN 1$" || fail "--cold did not replace the file"
run 2 test --junit "$PROG" "$PROG"
grep -q -- "--junit: .* is an input of this run" "$WORK/err" || fail "--junit over the program: $(cat "$WORK/err")"
same "$PROG" "$WORK/copy.st" "--junit overwrote the program"
run 2 test --junit "$WORK/fifo" "$PROG"
[ -p "$WORK/fifo" ] || fail "--junit replaced the FIFO"
run 2 run --virtual --cycles 1 --retain "$WORK/r.retain" --vcd "$WORK/r.retain" "$PROG"
printf '0ms,Main.plain,1\n' > "$WORK/stim.csv"
cp "$WORK/stim.csv" "$WORK/stim.orig"
run 2 run --virtual --cycles 1 --stimulus "$WORK/stim.csv" --vcd "$WORK/stim.csv" "$PROG"
run 2 run --virtual --cycles 1 --stimulus "$WORK/stim.csv" --retain "$WORK/stim.csv" "$PROG"
same "$WORK/stim.csv" "$WORK/stim.orig" "an output overwrote the stimulus file"
mkdir "$WORK/project" && cp "$PROG" "$WORK/project/main.st"
run 2 run --virtual --cycles 1 --vcd "$WORK/project/main.st" "$WORK/project"
same "$WORK/project/main.st" "$PROG" "--vcd overwrote a source found in a directory"
# An empty file holds nothing to lose: a cold start that writes it.
: > "$WORK/empty.retain"
run 0 run --virtual --cycles 1 --retain "$WORK/empty.retain" "$PROG"
[ -s "$WORK/empty.retain" ] || fail "the empty retain file was not written"

# 7. Write errors are reported and give exit 2.
run 0 run --virtual --cycles 1 --dump "$PROG"
"$STRUN" run --virtual --cycles 1 --dump "$PROG" >/dev/full 2>"$WORK/err"
status=$?
[ $status = 2 ] || fail "--dump to a full device: exit $status"
grep -q -- "--dump: cannot write" "$WORK/err" || fail "--dump to a full device: $(cat "$WORK/err")"
# A file size limit (ulimit -f, in KiB) makes writes past 1 KiB fail (EFBIG);
# SIGXFSZ is ignored so that the write returns the error. Stderr goes to a pipe.
limited() { ( trap '' XFSZ; ulimit -f 1; exec "$STRUN" "$@" ) 2>&1 >/dev/null; }
err=$(limited run --virtual --cycles 200 --vcd "$WORK/big.vcd" "$PROG"); status=$?
[ $status = 2 ] || fail "--vcd past the file size limit: exit $status ($err)"
grep -q -- "--vcd: cannot write" <<<"$err" || fail "--vcd past the file size limit: $err"
err=$(limited run --virtual --cycles 2 --retain "$WORK/big.retain" "$PROG"); status=$?
[ $status = 2 ] || fail "--retain past the file size limit: exit $status ($err)"
grep -q -- "--retain: cannot write" <<<"$err" || fail "--retain past the file size limit: $err"
[ -e "$WORK/big.retain" ] && fail "a failed retain save left a file"
echo "PASS"
