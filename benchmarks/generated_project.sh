#!/usr/bin/env bash
# The generated project of the start-up and LSP benchmarks: BLOCKS function
# blocks with their functions (~70 lines of ordinary PLC code each:
# declarations, IF/CASE/FOR, arithmetic, calls) and a Main calling them all.
#
# usage: benchmarks/generated_project.sh single BLOCKS FILE   one file
#        benchmarks/generated_project.sh files BLOCKS DIR     blockK.st each, and main.st
# (benchmarks/startup.sh sources it for the functions.)

block() {  # block K: function block BlockK and function ScaleK
    local k=$1
    cat <<ST
FUNCTION_BLOCK Block$k
VAR_INPUT
    enable : BOOL;
    setpoint : DINT;
    gain : REAL := 1.5;
END_VAR
VAR_OUTPUT
    out : DINT;
    busy : BOOL;
    alarm : BOOL;
END_VAR
VAR
    state : INT;
    acc : DINT;
    history : ARRAY[0..9] OF DINT;
    i : INT;
    timer : TON;
END_VAR
timer(IN := enable, PT := T#100ms);
CASE state OF
    0:
        IF enable THEN
            state := 1;
            acc := 0;
        END_IF;
    1:
        acc := acc + setpoint / 10;
        IF acc > setpoint THEN
            state := 2;
        ELSIF timer.Q THEN
            alarm := TRUE;
            state := 3;
        END_IF;
    2:
        FOR i := 0 TO 8 DO
            history[i] := history[i + 1];
        END_FOR;
        history[9] := acc;
        out := REAL_TO_DINT(DINT_TO_REAL(acc) * gain);
        state := 0;
    ELSE
        IF NOT enable THEN
            alarm := FALSE;
            state := 0;
        END_IF;
END_CASE;
busy := state <> 0;
END_FUNCTION_BLOCK

FUNCTION Scale$k : DINT
VAR_INPUT
    raw : DINT;
    low : DINT;
    high : DINT;
END_VAR
VAR
    span : DINT;
END_VAR
span := high - low;
IF span = 0 THEN
    Scale$k := low;
ELSE
    Scale$k := low + (raw * span) / 32767;
END_IF;
END_FUNCTION

ST
}

main_program() {  # main_program BLOCKS: the program calling them all
    echo "PROGRAM Main"
    echo "VAR"
    for (( k = 0; k < $1; k++ )); do echo "    b$k : Block$k;"; done
    echo "    total : DINT;"
    echo "END_VAR"
    for (( k = 0; k < $1; k++ )); do
        echo "b$k(enable := TRUE, setpoint := Scale$k(raw := total, low := 0, high := 1000));"
        echo "total := total + b$k.out;"
    done
    echo "END_PROGRAM"
}

project() {  # project BLOCKS FILE
    { for (( k = 0; k < $1; k++ )); do block $k; done; main_program $1; } >"$2"
}

project_files() {  # project_files BLOCKS DIR
    mkdir -p "$2"
    for (( k = 0; k < $1; k++ )); do block $k >"$2/block$k.st"; done
    main_program $1 >"$2/main.st"
}

if [[ "${BASH_SOURCE[0]}" == "$0" ]]; then
    set -eu
    case "${1:-}" in
        single) project "$2" "$3" ;;
        files) project_files "$2" "$3" ;;
        *) echo "usage: $0 single|files BLOCKS PATH" >&2; exit 2 ;;
    esac
fi
