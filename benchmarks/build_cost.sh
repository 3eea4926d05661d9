#!/usr/bin/env bash
# What a fresh build of strun costs, file by file (issue 28).
#
#   benchmarks/build_cost.sh [BUILD_DIR] [cmake --build args...]
#
# Configures BUILD_DIR (default /tmp/strun-build-cost, emptied first) from
# this source tree as `make run` does (Release, defaults otherwise), without
# ccache, with every compiler and linker run wrapped in /usr/bin/time, builds
# (default: `--target strun`) and prints the CPU time (user + system) and
# peak memory of each run, the total, and the wall time of the whole build.
# CPU seconds are what to compare on a shared machine: the wall time depends
# on what else runs.
set -eu
src=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir=${1:-/tmp/strun-build-cost}; shift || true
[[ $# -gt 0 ]] || set -- --target strun
rm -rf "$dir"; mkdir -p "$dir"
log="$dir/runs.log"
launcher="$dir/timed"
# The launcher: one line per run, "user system peak_kB wall what".
cat >"$launcher" <<'LAUNCH'
#!/bin/sh
log=$1; shift
what=link
prev=""
for a in "$@"; do
  [ "$prev" = "-c" ] && what=$a
  [ "$prev" = "-o" ] && [ "$what" = link ] && out=$a
  prev=$a
done
[ "$what" = link ] && what="link ${out:-?}"
exec /usr/bin/time -a -o "$log" -f "%U %S %M %e $what" "$@"
LAUNCH
chmod +x "$launcher"
export CCACHE_DISABLE=1
cmake -S "$src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release \
  "-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher;$log" "-DCMAKE_C_COMPILER_LAUNCHER=$launcher;$log" \
  "-DCMAKE_CXX_LINKER_LAUNCHER=$launcher;$log" >/dev/null
start=$(date +%s.%N)
/usr/bin/time -o "$dir/build.time" -f "%e %U %S" cmake --build "$dir/build" -j2 "$@" >"$dir/build.out" 2>&1 \
  || { tail -20 "$dir/build.out"; exit 1; }
read -r wall user sys <"$dir/build.time"
echo "build: wall ${wall} s, user ${user} s, system ${sys} s (cmake --build -j2 $*; includes the ANTLR generation)"
{ awk -v src="$src/" -v bdir="$dir/build/" '
  { cpu = $1 + $2; total += cpu; n++; what = $5; sub(src, "", what); sub(bdir, "", what)
    if ($3 > peak) { peak = $3; peakwhat = what }
    printf "%8.2f s %7.0f MB  %s\n", cpu, $3 / 1024, what }
  END { printf "total %.1f s of compiler and linker CPU in %d runs; peak %.0f MB (%s)\n", total, n, peak / 1024, peakwhat > "/dev/stderr" }' \
  "$log" 2>"$dir/summary.txt"; } | sort -rn >"$dir/per_run.txt"
cat "$dir/summary.txt"
echo "largest runs ($dir/per_run.txt has all):"
head -15 "$dir/per_run.txt"
