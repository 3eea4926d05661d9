#!/bin/sh
# LD/FBD (logic.xml) against the same logic in ST (logic.st): callgrind
# instruction counts per cycle (the count of a 4000-cycle run minus that of
# a 2000-cycle run, over 2000, so start-up and translation cancel out).
# Usage: benchmarks/graphical/compare.sh [path-to-strun]
strun=${1:-build/strun}
dir=$(dirname "$0")
count() { # $1 file, $2 cycles
    valgrind --tool=callgrind --callgrind-out-file=/dev/null "$strun" run --virtual --cycles "$2" --quiet "$dir/$1" 2>&1 |
        sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
}
for f in logic.st logic.xml; do
    a=$(count $f 2000); b=$(count $f 4000)
    echo "$f $(( (b - a) / 2000 ))"
done | awk '{ per[NR] = $2; printf "%-10s %8d instructions per cycle\n", $1, $2 } END { printf "LD/FBD / ST: %.3f\n", per[2] / per[1] }'
