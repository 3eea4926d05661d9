#!/bin/sh
# One program of the diagnostics gallery (tests/diagnostics/README.md):
#   gallery_check.sh STRUN GALLERY_DIR NAME [--update]
# runs `strun check --color never [ARGS] NAME.st` in GALLERY_DIR (ARGS from
# NAME.args when present; `--color` there replaces `--color never`), and compares its stderr plus a last line
# `[exit N]` with NAME.expected; --update writes NAME.expected instead.
# Every location printed must be in a file of the gallery: never in strun's
# embedded library sources.
strun=$1 dir=$2 name=$3 mode=$4
cd "$dir" || exit 2
args=""
[ -f "$name.args" ] && args=$(cat "$name.args")
actual=$(mktemp)
trap 'rm -f "$actual"' EXIT
color="--color never"
case "$args" in *--color*) color="" ;; esac
# shellcheck disable=SC2086
"$strun" check $color $args "$name.st" 2>"$actual" >/dev/null
echo "[exit $?]" >>"$actual"
if [ "$mode" = "--update" ]; then
    cp "$actual" "$name.expected"
    exit 0
fi
status=0
# Locations (FILE:LINE:COL: error|warning|note:, or "file":"..." in JSON) must name gallery files.
for f in $(sed -n -e 's/^\([^ :]*\):[0-9]*:[0-9]*: \(error\|warning\|note\):.*/\1/p' -e 's/.*"file":"\([^"]*\)".*/\1/p' "$actual" | sort -u); do
    if [ ! -f "$f" ]; then
        echo "a diagnostic points into '$f', which is not a file of the program"
        status=1
    fi
done
if ! diff -u "$name.expected" "$actual"; then
    echo "the output of $name.st differs from $name.expected (regenerate: $0 STRUN DIR $name --update, then review)"
    status=1
fi
exit $status
