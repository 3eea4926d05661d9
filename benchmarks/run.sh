#!/usr/bin/env bash
# Runs every benchmark workload on strun and on Lua 5.4 and prints, per
# workload, the best wall-clock time of each side and the ratio strun/Lua.
# When luajit is installed, also LuaJIT's interpreter (luajit -joff, on the
# Lua twin made Lua 5.1 code by luajit_twin below), and when gcc is
# installed and the workload has a C twin NAME.c, that twin at gcc -O2.
# Fails (exit 1) when a run fails or a checksum differs from strun's.
#
# usage: benchmarks/run.sh [path-to-strun] [workload...]
#   path-to-strun  default build/strun
#   workload       names from benchmarks/workloads (default: all, in the order below)
# The sides of a workload run in turn, one run of each per round, so that
# the machine's drift over seconds (tens of percent on a shared VM) moves
# all of them alike instead of the side that happened to run last.
# environment: BENCH_REPEATS (default 3) rounds, each side's best run counts;
#              LUA (default lua5.4) the Lua interpreter;
#              LUAJIT (default luajit; empty: no LuaJIT column), CC (default
#              gcc; empty: no C column);
#              BENCH_INSTRUCTIONS=1 also counts the instructions each side
#              executes (valgrind --tool=callgrind; slow, but exact where wall
#              times on a shared machine are noisy).
set -u

bench_dir=$(cd "$(dirname "$0")" && pwd)
workload_dir="$bench_dir/workloads"
strun=${1:-build/strun}
shift $(( $# > 0 ? 1 : 0 ))
repeats=${BENCH_REPEATS:-3}
lua=${LUA:-lua5.4}
luajit=${LUAJIT-luajit}
cc=${CC-gcc}
if [[ -n "$luajit" ]] && ! command -v "$luajit" >/dev/null 2>&1; then luajit=""; fi
if [[ -n "$cc" ]] && ! command -v "$cc" >/dev/null 2>&1; then cc=""; fi

default_workloads=(int_loops real_math sort sieve fb_calls strings state_machine func_calls conversions fb_methods collatz
                   many_args fb_io nested_arith bubble_sort string_build case_machine)
if (( $# > 0 )); then workloads=("$@"); else workloads=("${default_workloads[@]}"); fi

if [[ ! -x "$strun" ]]; then
    echo "run.sh: strun not found or not executable at '$strun' (build it with 'make build')" >&2
    exit 2
fi
if ! command -v "$lua" >/dev/null 2>&1; then
    echo "run.sh: Lua interpreter '$lua' not found (install the Debian package lua5.4)" >&2
    exit 2
fi
if ! [[ "$repeats" =~ ^[1-9][0-9]*$ ]]; then
    echo "run.sh: BENCH_REPEATS must be a positive integer, got '$repeats'" >&2
    exit 2
fi
for name in "${workloads[@]}"; do
    for ext in st lua; do
        if [[ ! -f "$workload_dir/$name.$ext" ]]; then
            echo "run.sh: no workload file $workload_dir/$name.$ext" >&2
            exit 2
        fi
    done
done

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Per workload, each side is a function run_<side> that runs it once with
# its output in $scratch/<side>.out and its errors in $scratch/<side>.err.
# in_turn SIDE...: runs the sides one after the other, $repeats rounds;
# sets best[SIDE] to each side's fastest run in ns and rc[SIDE] to its first
# non-zero exit status (0 if every run succeeded; a failed side runs no more).
declare -A best rc
in_turn() {
    local side r start end ns status
    for side in "$@"; do best[$side]=""; rc[$side]=0; done
    for (( r = 0; r < repeats; r++ )); do
        for side in "$@"; do
            (( rc[$side] != 0 )) && continue
            start=$(date +%s%N)
            "run_$side"
            status=$?
            end=$(date +%s%N)
            if (( status != 0 )); then
                rc[$side]=$status
                continue
            fi
            ns=$(( end - start ))
            if [[ -z "${best[$side]}" ]] || (( ns < best[$side] )); then best[$side]=$ns; fi
        done
    done
}

seconds() { awk -v ns="$1" 'BEGIN { printf "%.3f", ns / 1e9 }'; }

# instructions CMD...: the instructions CMD executes (callgrind's Ir total).
instructions() {
    valgrind --tool=callgrind --callgrind-out-file="$scratch/cg.out" "$@" >/dev/null 2>"$scratch/cg.err" || { echo "-"; return; }
    sed -n 's/^summary: *//p' "$scratch/cg.out" | head -n1
}
count_instructions=${BENCH_INSTRUCTIONS:-0}
if [[ "$count_instructions" == 1 ]] && ! command -v valgrind >/dev/null 2>&1; then
    echo "run.sh: BENCH_INSTRUCTIONS=1 needs valgrind (Debian package valgrind)" >&2
    exit 2
fi
log_sum=0
log_count=0

echo "strun: $strun   lua: $($lua -v 2>&1 | head -n1 | cut -d" " -f1-2)   luajit -joff: ${luajit:-none}   C: ${cc:+$cc -O2}   best of $repeats rounds, the sides in turn"
row_format="%-14s %9s %9s %13s %9s %10s %9s %8s  %s\n"
printf "$row_format" "workload" "strun s" "lua s" "strun/lua" "luajit s" "strun/jit" "C s" "strun/C" "checksum"
printf "$row_format" "--------" "-------" "-----" "---------" "--------" "---------" "---" "-------" "--------"
jit_log_sum=0 jit_log_count=0 c_log_sum=0 c_log_count=0

# The Lua twin as Lua 5.1 (LuaJIT) reads it: 5.1 has no integer division
# `a // b` (math.floor(a / b) is exact below 2^53, where the workloads stay)
# and no math.tointeger (its numbers are all doubles).
luajit_twin() {
    sed -E -e 's/math\.tointeger\(([^()]*)\)/(\1)/g' \
        -e '/^[[:space:]]*--/!s#([A-Za-z_][A-Za-z0-9_.]*|[0-9]+) // ([A-Za-z_][A-Za-z0-9_.]*|[0-9]+)#math.floor(\1 / \2)#g' "$1"
}

failed=0
for name in "${workloads[@]}"; do
    st_file="$workload_dir/$name.st"
    lua_file="$workload_dir/$name.lua"

    # The sides of this workload: strun and Lua always, LuaJIT's
    # interpreter and the C twin when there are.
    sides=(strun lua)
    run_strun() { "$strun" run --virtual --stmt-cost 0ns --cycles 1 --task Main --dump "$st_file" >"$scratch/strun.out" 2>"$scratch/strun.err"; }
    run_lua() { "$lua" "$lua_file" >"$scratch/lua.out" 2>"$scratch/lua.err"; }
    jit_col="-" jit_ratio="-" c_col="-" c_ratio="-"
    if [[ -n "$luajit" ]]; then
        jit_file="$scratch/$name.luajit.lua"
        luajit_twin "$lua_file" >"$jit_file"
        run_jit() { "$luajit" -joff "$jit_file" >"$scratch/jit.out" 2>"$scratch/jit.err"; }
        sides+=(jit)
    fi
    if [[ -n "$cc" && -f "$workload_dir/$name.c" ]]; then
        if "$cc" -O2 -o "$scratch/$name.native" "$workload_dir/$name.c" 2>"$scratch/cc.err"; then
            run_c() { "$scratch/$name.native" >"$scratch/c.out" 2>"$scratch/c.err"; }
            sides+=(c)
        else
            failed=1 c_col="FAILED"
            sed -n '1,5s/^/    cc: /p' "$scratch/cc.err"
        fi
    fi
    in_turn "${sides[@]}"
    strun_ns=${best[strun]} strun_rc=${rc[strun]}
    lua_ns=${best[lua]} lua_rc=${rc[lua]}

    if (( strun_rc != 0 || lua_rc != 0 )); then
        failed=1
        strun_col=$( (( strun_rc == 0 )) && seconds "$strun_ns" || echo "exit $strun_rc")
        lua_col=$( (( lua_rc == 0 )) && seconds "$lua_ns" || echo "exit $lua_rc")
        printf "$row_format" "$name" "$strun_col" "$lua_col" "-" "" "" "" "" "FAILED"
        (( strun_rc != 0 )) && sed -n '1,5s/^/    strun: /p' "$scratch/strun.err"
        (( lua_rc != 0 )) && sed -n '1,5s/^/    lua: /p' "$scratch/lua.err"
        continue
    fi

    ratio=$(awk -v s="$strun_ns" -v l="$lua_ns" 'BEGIN { printf "%.2f", s / l }')
    if values=$("$lua" "$bench_dir/same_checksum.lua" "$scratch/strun.out" "$scratch/lua.out"); then
        verdict="ok (${values% *})"
    else
        failed=1
        verdict="DIFFERS: strun ${values% *}, lua ${values#* }"
    fi
    log_sum=$(awk -v a="$log_sum" -v r="$ratio" 'BEGIN { printf "%.6f", a + log(r) }')
    log_count=$(( log_count + 1 ))

    # LuaJIT's interpreter and the C twin: their output must be strun's checksum too.
    if [[ -n "$luajit" ]]; then
        if (( rc[jit] == 0 )) && "$lua" "$bench_dir/same_checksum.lua" "$scratch/strun.out" "$scratch/jit.out" >/dev/null; then
            jit_col=$(seconds "${best[jit]}")
            jit_ratio=$(awk -v s="$strun_ns" -v l="${best[jit]}" 'BEGIN { printf "%.2f", s / l }')
            jit_log_sum=$(awk -v a="$jit_log_sum" -v r="$jit_ratio" 'BEGIN { printf "%.6f", a + log(r) }')
            jit_log_count=$(( jit_log_count + 1 ))
        else
            failed=1 jit_col="FAILED"
        fi
    fi
    if [[ " ${sides[*]} " == *" c "* ]]; then
        if (( rc[c] == 0 )) && "$lua" "$bench_dir/same_checksum.lua" "$scratch/strun.out" "$scratch/c.out" >/dev/null; then
            c_col=$(seconds "${best[c]}")
            c_ratio=$(awk -v s="$strun_ns" -v l="${best[c]}" 'BEGIN { printf "%.1f", s / l }')
            c_log_sum=$(awk -v a="$c_log_sum" -v s="$strun_ns" -v l="${best[c]}" 'BEGIN { printf "%.6f", a + log(s / l) }')
            c_log_count=$(( c_log_count + 1 ))
        else
            failed=1 c_col="FAILED"
        fi
    fi
    printf "$row_format" "$name" "$(seconds "$strun_ns")" "$(seconds "$lua_ns")" "$ratio" "$jit_col" "$jit_ratio" "$c_col" "$c_ratio" "$verdict"
    if [[ "$count_instructions" == 1 ]]; then
        strun_ir=$(instructions "$strun" run --virtual --stmt-cost 0ns --cycles 1 --task Main --dump "$st_file")
        lua_ir=$(instructions "$lua" "$lua_file")
        printf "%-14s %s\n" "" "instructions: strun $strun_ir, lua $lua_ir, ratio $(awk -v s="$strun_ir" -v l="$lua_ir" 'BEGIN { if (l > 0) printf "%.2f", s / l; else print "-" }')"
    fi
done
if (( log_count > 0 )); then
    geo() { (( $2 > 0 )) && awk -v a="$1" -v n="$2" 'BEGIN { printf "%.2f", exp(a / n) }' || echo "-"; }
    printf "$row_format" "geomean" "" "" "$(geo "$log_sum" "$log_count")" "" "$(geo "$jit_log_sum" "$jit_log_count")" "" "$(geo "$c_log_sum" "$c_log_count")" ""
fi

if (( failed )); then
    echo "run.sh: at least one workload failed or disagreed with strun's checksum" >&2
    exit 1
fi
