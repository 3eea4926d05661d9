#!/bin/sh
# Every compile message of the conformance suite and the gallery has a code
# of its own kind: none may fall into the catch-all E0999/W0999, which would
# mean a message was reworded or added without a classification rule
# (interpreter/source/diagnostic_codes.cpp, decision 0160).
# $1: strun, $2: tests/conformance, $3: tests/diagnostics/gallery
strun="$1"
found=0
for f in $(find "$2" "$3" -name '*.st' | sort); do
    out=$("$strun" check --diagnostics-format json "$f" 2>&1 | grep -E '"code":"[EW]0999"')
    if [ -n "$out" ]; then
        echo "$f: $out"
        found=1
    fi
done
exit $found
