#!/bin/sh
# FILE.DirCopy (decision 0376): a tree copied with its subdirectories (an
# empty one included), without them, without overwriting; a missing source,
# a destination inside the source, paths out of the sandbox and a symbolic
# link leading out are refused and nothing appears outside.
#   caa_dircopy_test.sh STRUN TEST_SOURCE_DIR
set -eu
strun=$1
src=$2
. "$src/sandbox_setup.sh"
box=$tmp/box
mkdir -p "$box/src/sub/deeper" "$box/src/empty" "$box/keep" "$box/copy" "$box/linked"
printf 'top' > "$box/src/a.txt"
printf 'below' > "$box/src/sub/b.txt"
printf 'deep' > "$box/src/sub/deeper/c.txt"
printf 'old' > "$box/keep/a.txt"
ln -s "$tmp/outside/secret.txt" "$box/linked/secret.txt"
"$strun" run --virtual --cycles 2 --dump --files "$box" "$src/caa_dircopy.st" > "$tmp/dump.json"
for expect in '"wholeBusy": *true' '"wholeDone": *true' '"wholeErr": *"NO_ERROR"' '"flatDone": *true' '"keepDone": *true' \
    '"missingErr": *"NOT_EXIST"' '"insideErr": *"WRONG_PARAMETER"' '"escapeErr": *"FILE_OPERATION_DENIED"' \
    '"absoluteErr": *"FILE_OPERATION_DENIED"' '"viaLinkErr": *"FILE_OPERATION_DENIED"'; do
    grep -q "$expect" "$tmp/dump.json" || fail "dump lacks $expect"
done
[ "$(cat "$box/copy/whole/a.txt")" = top ] || fail "a.txt not copied"
[ "$(cat "$box/copy/whole/sub/b.txt")" = below ] || fail "sub/b.txt not copied"
[ "$(cat "$box/copy/whole/sub/deeper/c.txt")" = deep ] || fail "sub/deeper/c.txt not copied"
[ -d "$box/copy/whole/empty" ] || fail "the empty directory was not copied"
[ "$(cat "$box/flat/a.txt")" = top ] || fail "flat a.txt"
[ ! -e "$box/flat/sub" ] || fail "a subdirectory was copied without xRecursive"
[ "$(cat "$box/keep/a.txt")" = old ] || fail "an existing file was overwritten without xOverWrite"
[ "$(cat "$box/keep/sub/b.txt")" = below ] || fail "keep/sub/b.txt not copied"
[ ! -e "$box/src/sub/again" ] || fail "the copy into the source was started"
[ ! -e "$tmp/escaped" ] || fail "a directory appeared outside"
[ ! -e "$box/fromlink/secret.txt" ] || fail "the file behind a link out was copied"
[ "$(ls "$tmp/outside")" = "secret.txt" ] || fail "something appeared outside"
echo PASS
