#!/bin/bash
# Retain files are data from outside (issue 30, decision 0251): a crafted
# file with a right checksum but values their types cannot hold restores
# none of them (warning, initial value); an oversized file is not read
# whole; the file is written and read in pieces.
#   retain_values_test.sh STRUN TESTDIR
set -u
STRUN=$1
HERE=$2
WORK=$(mktemp -d /tmp/strun-retain-values-XXXXXX)
trap 'rm -rf "$WORK"' EXIT
FILE=$WORK/plc.retain
fail() { echo "FAIL: $*"; exit 1; }
field() { # field NAME JSON: the value after "NAME": (number, string or bool)
    grep -o "\"$1\": [^,}]*" <<<"$2" | head -1 | sed 's/^[^:]*: //'
}

"$STRUN" run --virtual --cycles 1 --retain "$FILE" "$HERE/retain_values.st" 2>/dev/null || fail "first run"
# Rewrite values with bytes no variable of their type can hold, and the checksum to match.
python3 - "$FILE" <<'PY' || fail "crafting the file"
import sys
path = sys.argv[1]
lines = open(path, "rb").read().split(b"\n")
crafted = {
    b"Main.s": "41" * 11,                   # STRING(10): 11 bytes, no terminator
    b"Main.w": "4100" * 5,                  # WSTRING(4): no terminator
    b"Main.b": "02",                        # BOOL 2
    b"Main.c": "0700",                      # Color 7: no such value
    b"Main.r": "1400",                      # Small 20: outside 0..10
    b"Main.p": None,                        # struct: flag byte 3
    b"Main.flags": "00010200",              # element 2 is BOOL 2
}
out = []
for line in lines[:-2]:  # the END line and the empty piece after it
    parts = line.split(b"\t")
    if len(parts) == 3 and parts[0] in crafted:
        hexed = crafted[parts[0]]
        if hexed is None:
            hexed = "03" + parts[2].decode()[2:]
        parts[2] = hexed.encode()
        line = b"\t".join(parts)
    out.append(line)
body = b"\n".join(out) + b"\n"
h = 1469598103934665603
for c in body:
    h = ((h ^ c) * 1099511628211) & 0xFFFFFFFFFFFFFFFF
open(path, "wb").write(body + b"END %d %016x\n" % (len(out) - 1, h))
PY
out=$("$STRUN" run --virtual --cycles 1 --dump --retain "$FILE" "$HERE/retain_values.st" 2>"$WORK/err") || fail "run on the crafted file: $(cat "$WORK/err")"
grep -q "not a complete retain file" "$WORK/err" && fail "the crafted checksum is wrong: $(cat "$WORK/err")"
[ "$(field s "$out")" = '"init"' ] || fail "an unterminated STRING was restored: $out"
[ "$(field sLen "$out")" = 4 ] || fail "LEN of the STRING: $out"
[ "$(field b "$out")" = false ] || fail "BOOL 2 was restored: $out"
[ "$(field bIsTrue "$out")" = false ] || fail "b = TRUE: $out"
[ "$(field c "$out")" = '"Green"' ] || fail "an enumeration value outside its type was restored: $out"
[ "$(field r "$out")" = 5 ] || fail "a subrange value outside its range was restored: $out"
[ "$(field good "$out")" = 2 ] || fail "a valid value was not restored: $out"
for v in Main.s Main.w Main.b Main.c Main.r Main.p Main.flags; do
    grep -q "'$v': the saved value is not a valid" "$WORK/err" || fail "no warning for $v: $(cat "$WORK/err")"
done
grep -q "'Main.flags': .*element 2: a BOOL byte of 2" "$WORK/err" || fail "the warning does not say which element: $(cat "$WORK/err")"
grep -q "'Main.s': .*STRING(10) without its terminator" "$WORK/err" || fail "the STRING warning: $(cat "$WORK/err")"

# A retain file far larger than this project's retained variables can make is
# not read (a sparse 1 GiB file: only its first pieces are read).
{ printf 'STRUN-RETAIN 1\n'; } > "$WORK/huge.retain"
truncate -s 1G "$WORK/huge.retain"
out=$(timeout 20 "$STRUN" run --virtual --cycles 1 --dump --retain "$WORK/huge.retain" "$HERE/retain_values.st" 2>"$WORK/err") || fail "run on a huge retain file: $?"
grep -q "is larger than the [0-9]* bytes a retain file of this project can have; cold start" "$WORK/err" || fail "no size warning: $(cat "$WORK/err")"
[ "$(field good "$out")" = 1 ] || fail "the huge file was used: $out"
[ "$(stat -c %s "$WORK/huge.retain")" -lt 100000 ] || fail "the huge file was not replaced by the saved values"
echo "PASS"
