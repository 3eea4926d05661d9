#!/usr/bin/env bash
# The cost of --vcd: runs benchmarks/vcd/plant_100.st (100 recorded
# variables, 60000 cycles on the virtual clock) without and with --vcd and
# prints the best wall-clock time of each and the ratio. Exit 1 when the
# recorded run is more than 2x the unrecorded one (the issue's budget).
#
# usage: benchmarks/vcd/run_vcd_bench.sh [path-to-strun]
# environment: BENCH_REPEATS (default 5) runs per side, best one counts.
set -u
bench_dir=$(cd "$(dirname "$0")" && pwd)
strun=${1:-build/strun}
repeats=${BENCH_REPEATS:-5}
workload="$bench_dir/plant_100.st"
if [[ ! -x "$strun" ]]; then
    echo "run_vcd_bench.sh: strun not found at '$strun'" >&2
    exit 2
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

best() {  # best of $repeats runs of "$@", in ns
    local b="" s e ns
    for (( r = 0; r < repeats; r++ )); do
        s=$(date +%s%N)
        "$@" >/dev/null 2>"$scratch/err" || { echo "run failed: $*" >&2; cat "$scratch/err" >&2; exit 1; }
        e=$(date +%s%N)
        ns=$(( e - s ))
        if [[ -z "$b" || $ns -lt $b ]]; then b=$ns; fi
    done
    echo "$b"
}

base=(run --virtual --stmt-cost 10ns --for T#60s --quiet "$workload")
plain=$(best "$strun" "${base[@]}")
recorded=$(best "$strun" "${base[@]}" --vcd "$scratch/out.vcd" --watch 'P.flags*' --watch 'P.counters*' --watch 'P.levels*')
signals=$(grep -c '^\$var' "$scratch/out.vcd")
bytes=$(stat -c %s "$scratch/out.vcd")
ratio=$(awk -v a="$recorded" -v b="$plain" 'BEGIN { printf "%.2f", a / b }')
printf 'without --vcd  %8.3f s\n' "$(awk -v n="$plain" 'BEGIN { print n / 1e9 }')"
printf 'with --vcd     %8.3f s  (%s signals incl. the task, %s bytes of VCD)\n' \
    "$(awk -v n="$recorded" 'BEGIN { print n / 1e9 }')" "$signals" "$bytes"
printf 'ratio          %8s x\n' "$ratio"
awk -v r="$ratio" 'BEGIN { exit (r <= 2.0) ? 0 : 1 }' || { echo "over the 2x budget" >&2; exit 1; }
