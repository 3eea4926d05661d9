#!/bin/sh
# CAA File cannot leave the --files directory through symbolic links (the
# sandbox of decision 0221, through CAA's blocks, decision 0324): every
# operation through a link is refused with FILE_OPERATION_DENIED (5114),
# deleting a link removes only the link, and nothing outside changes.
#   caa_files_sandbox_test.sh STRUN TEST_SOURCE_DIR
set -eu
strun=$1
src=$2
. "$src/sandbox_setup.sh"
"$strun" run --virtual --cycles 3 --dump --files "$tmp/box" "$src/caa_files_symlinks.st" > "$tmp/dump.json"
for v in openDirErr openFileErr sizeErr mkDirErr listLinkErr listBelowErr; do
    grep -q "\"$v\": *5114" "$tmp/dump.json" || fail "$v is not FILE_OPERATION_DENIED"
done
grep -q '"deleteErr": *0' "$tmp/dump.json" || fail "deleting the link failed"
[ ! -e "$tmp/box/secret.txt" ] && [ ! -L "$tmp/box/secret.txt" ] || fail "the link is still there"
[ "$(cat "$tmp/outside/secret.txt")" = "secret" ] || fail "the file outside changed"
[ "$(ls "$tmp/outside")" = "secret.txt" ] || fail "something appeared outside"
echo PASS
