#!/bin/sh
# The bench in one command: the tank (plant.py, a Modbus TCP device on port
# 5020) and strun controlling it through mapping.json for SECONDS (default
# 20) of real time; strun also serves its image on port 5021 for an HMI.
#   sh programs/modbus_bench/run.sh [SECONDS] [STRUN]
dir=$(dirname "$0")
seconds=${1:-20}
strun=${2:-build/strun}
# A Python that has pymodbus (Debian's python3-pymodbus).
python=python3
"$python" -c 'import pymodbus' 2>/dev/null || python=/usr/bin/python3
"$python" "$dir/plant.py" 5020 &
plant=$!
trap 'kill $plant 2>/dev/null' EXIT INT TERM
sleep 1
"$strun" run --for "${seconds}s" --modbus-client "$dir/mapping.json" --modbus 127.0.0.1:5021 --dump "$dir/tank_control.st"
