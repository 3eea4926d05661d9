#!/bin/sh
# The Modbus server's measurements (closing note of issue 27; not a test):
# a 1 ms real-clock task (server_image.st) with --modbus, (a) alone, (b) with
# 8 clients polling 10 holding registers at 100 Hz, (c) with 16 clients as
# fast as they are answered. For each: the task's start latency (p50, p99,
# max, from --trace), overruns, and the requests per second answered.
#   [STRUN_ARGS=--realtime] sh tests/modbus/measure.sh build/strun build/tests/modbus/modbus_load [SECONDS]
strun=$1
load=$2
seconds=${3:-10}
dir=$(dirname "$0")
port=15502
tmp=$(mktemp -d)
for case in alone 8x100Hz 16xmax; do
    "$strun" run $STRUN_ARGS --for "${seconds}s" --trace --dump --modbus 127.0.0.1:$port "$dir/server_image.st" \
        >"$tmp/$case.json" 2>"$tmp/$case.trace" &
    pid=$!
    sleep 1
    case $case in
        alone) echo "requests/s 0 failed 0" >"$tmp/$case.load" ;;
        8x100Hz) "$load" $port 8 $((seconds - 2)) 100 >"$tmp/$case.load" ;;
        16xmax) "$load" $port 16 $((seconds - 2)) 0 >"$tmp/$case.load" ;;
    esac
    wait $pid
    python3 - "$case" "$tmp/$case.trace" "$tmp/$case.json" "$tmp/$case.load" <<'PY'
import json, re, sys
case, trace, dump, load = sys.argv[1:]
units = {"d": 86400e9, "h": 3600e9, "m": 60e9, "s": 1e9, "ms": 1e6, "us": 1e3, "ns": 1}
def ns(text):
    return sum(float(v) * units[u] for v, u in re.findall(r"([\d.]+)(ms|us|ns|d|h|m|s)", text[2:]))
lat = []
for line in open(trace):
    parts = line.split()
    if len(parts) >= 3 and parts[2] == "start" and parts[0].startswith("T#"):
        t = ns(parts[0])
        lat.append((t % 1e6) / 1e3)  # us after the 1 ms grid point
lat = sorted(lat[1000:])  # the first second: start-up
task = json.load(open(dump))["tasks"][0]
p = lambda q: lat[min(len(lat) - 1, int(q * len(lat)))]
print("%-8s cycles %6d overruns %4d  latency us: p50 %6.1f  p99 %6.1f  max %7.1f   %s" % (
    case, task["cycles"], task["overruns"], p(0.5), p(0.99), lat[-1], open(load).read().strip()))
PY
done
rm -rf "$tmp"
