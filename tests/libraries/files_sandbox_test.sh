#!/bin/sh
# The file blocks cannot leave the --files directory through symbolic links
# (decision 0221): a link to a directory or a file outside is refused with
# ADS error 1827, nothing appears outside, and what the program writes
# stays in the sandbox after the run.
#   files_sandbox_test.sh STRUN TEST_SOURCE_DIR
set -eu
strun=$1
src=$2
. "$src/sandbox_setup.sh"
echo "inside line" > "$tmp/box/inside.txt"
"$strun" run --virtual --cycles 12 --dump --files "$tmp/box" "$src/files_symlinks.st" > "$tmp/dump.json"
grep -q '"linkDirErr": *1827' "$tmp/dump.json" || fail "a directory link was followed"
grep -q '"linkFileErr": *1827' "$tmp/dump.json" || fail "a file link was followed"
grep -q '"linkMkDirErr": *1827' "$tmp/dump.json" || fail "a directory was made through a link"
grep -q '"insideLine": *"inside line\\n"' "$tmp/dump.json" || fail "the file inside was not read"
grep -q '"wroteOk": *true' "$tmp/dump.json" || fail "the write failed"
[ "$(cat "$tmp/box/written.txt")" = "from the PLC" ] || fail "written.txt is not in the sandbox"
[ ! -e "$tmp/outside/newdir" ] || fail "a directory appeared outside"
[ "$(ls "$tmp/outside")" = "secret.txt" ] || fail "something appeared outside"
echo PASS
