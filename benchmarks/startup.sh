#!/usr/bin/env bash
# Start-up benchmark: what a user waits for before the first cycle runs.
#   one_line  `strun run --virtual --cycles 1` of a one-statement program
#             (against `lua5.4 -e` of one statement)
#   check_20k `strun check` of a generated 20 000-line project (290 function
#             blocks with their functions, one program calling them)
#   check_30k the same with 435 blocks: 30 000 lines (issue 11's size of
#             a large library such as OSCAT BASIC)
#   check_files  check_20k's project as 291 files in one directory
# Prints the best wall-clock time of each (BENCH_REPEATS runs, default 5) and,
# when valgrind is installed, the instructions callgrind counts for one run
# (repeatable where wall times are noisy; BENCH_INSTRUCTIONS=0 skips them).
#
# usage: benchmarks/startup.sh [path-to-strun]
set -u
strun=${1:-build/strun}
repeats=${BENCH_REPEATS:-5}
lua=${LUA:-lua5.4}
if [[ ! -x "$strun" ]]; then
    echo "startup.sh: strun not found at '$strun' (build it with 'make build')" >&2
    exit 2
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

instructions() {  # instructions CMD...: callgrind's instruction count of one run, or "-"
    if [[ "${BENCH_INSTRUCTIONS:-1}" == 0 ]] || ! command -v valgrind >/dev/null 2>&1; then echo "-"; return; fi
    valgrind --tool=callgrind --callgrind-out-file="$scratch/cg.out" "$@" >/dev/null 2>"$scratch/cg.err" || { echo "-"; return; }
    awk '/^summary:/ { printf "%.1fM", $2 / 1e6 }' "$scratch/cg.out"
}

best_ms() {  # best_ms CMD...: the fastest of $repeats runs in ms (exit 1 if a run fails)
    local best="" r start end ns
    for (( r = 0; r < repeats; r++ )); do
        start=$(date +%s%N)
        "$@" >/dev/null 2>"$scratch/err" || { sed 's/^/    /' "$scratch/err" >&2; return 1; }
        end=$(date +%s%N)
        ns=$(( end - start ))
        if [[ -z "$best" ]] || (( ns < best )); then best=$ns; fi
    done
    awk -v ns="$best" 'BEGIN { printf "%.1f", ns / 1e6 }'
}

printf 'PROGRAM Main VAR x : INT; END_VAR x := x + 1; END_PROGRAM\n' >"$scratch/one_line.st"

# The generated project (blocks, main program): benchmarks/generated_project.sh.
source "$(dirname "${BASH_SOURCE[0]}")/generated_project.sh"

gen="$scratch/check_20k.st"
project 290 "$gen"
gen30="$scratch/check_30k.st"
project 435 "$gen30"
project_files 290 "$scratch/files"
lines=$(wc -l <"$gen")

echo "strun: $strun   best of $repeats runs each (wall ms); instructions of one run (callgrind)"
printf '%-12s %10s %10s %12s %12s\n' "start-up" "strun ms" "lua ms" "strun instr" "lua instr"
one=$(best_ms "$strun" run --virtual --cycles 1 "$scratch/one_line.st") || exit 1
one_i=$(instructions "$strun" run --virtual --cycles 1 "$scratch/one_line.st")
lua_one="-"; lua_i="-"
if command -v "$lua" >/dev/null 2>&1; then
    lua_one=$(best_ms "$lua" -e 'local x = 0; x = x + 1')
    lua_i=$(instructions "$lua" -e 'local x = 0; x = x + 1')
fi
printf '%-12s %10s %10s %12s %12s\n' "one_line" "$one" "$lua_one" "$one_i" "$lua_i"
chk=$(best_ms "$strun" check "$gen") || exit 1
chk_i=$(instructions "$strun" check "$gen")
printf '%-12s %10s %10s %12s %12s   (%d lines, %.0f lines/s)\n' "check_20k" "$chk" "-" "$chk_i" "-" "$lines" "$(awk -v l="$lines" -v ms="$chk" 'BEGIN { print l / (ms / 1000) }')"
lines30=$(wc -l <"$gen30")
chk30=$(best_ms "$strun" check "$gen30") || exit 1
chk30_i=$(instructions "$strun" check "$gen30")
printf '%-12s %10s %10s %12s %12s   (%d lines, %.0f lines/s)\n' "check_30k" "$chk30" "-" "$chk30_i" "-" "$lines30" "$(awk -v l="$lines30" -v ms="$chk30" 'BEGIN { print l / (ms / 1000) }')"
chkf=$(best_ms "$strun" check "$scratch/files") || exit 1
chkf_i=$(instructions "$strun" check "$scratch/files")
printf '%-12s %10s %10s %12s %12s   (%d files)\n' "check_files" "$chkf" "-" "$chkf_i" "-" "$(ls "$scratch/files" | wc -l)"
