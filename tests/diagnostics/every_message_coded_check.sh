#!/bin/sh
# Every compile message of the conformance suite and the gallery carries a
# code that the catalogue explains (`strun explain CODE`): codes are given
# where a diagnostic is raised (decision 0298), and a code missing from the
# catalogue, or a message without one, fails here.
# $1: strun, $2: tests/conformance, $3: tests/diagnostics/gallery
strun="$1"
codes=$(mktemp)
trap 'rm -f "$codes"' EXIT
found=0
for f in $(find "$2" "$3" -name '*.st' | sort); do
    out=$("$strun" check --diagnostics-format json "$f" 2>&1)
    # A diagnostic object without a code, or with an empty one.
    if printf '%s\n' "$out" | grep -E '"severity":"(error|warning)"' | grep -vqE '"code":"[EW][0-9]{4}"'; then
        echo "$f: a diagnostic without a code:"
        printf '%s\n' "$out" | grep -E '"severity"' | grep -vE '"code":"[EW][0-9]{4}"' | head -3
        found=1
    fi
    printf '%s\n' "$out" | grep -oE '"code":"[EW][0-9]{4}"' | cut -d'"' -f4 >> "$codes"
done
for code in $(sort -u "$codes"); do
    if ! "$strun" explain "$code" > /dev/null 2>&1; then
        echo "code $code is not in the catalogue (strun explain $code fails)"
        found=1
    fi
done
[ -s "$codes" ] || { echo "no diagnostics at all: the check saw nothing"; found=1; }
exit $found
