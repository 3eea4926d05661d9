#!/bin/sh
# The Neovim and Emacs set-ups of docs/editors.md, tried for real: headless
# nvim with its built-in LSP client, Emacs in batch mode with eglot, each on
# a two-file project (diagnostics with their code, hover, definition into
# the other file). An editor that is not installed is skipped; all missing:
# exit 77 (ctest: skipped). usage: run.sh STRUN
set -u
STRUN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
HERE=$(cd "$(dirname "$0")" && pwd)
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
cd "$WORK" || exit 1
cat > main.st <<'ST'
PROGRAM Main
VAR
    counter : INT;
    fb : FB_Count;
END_VAR
counter := counter + 1;
fb(step := 2);
counter := missing;
END_PROGRAM
ST
cat > fb.st <<'ST'
FUNCTION_BLOCK FB_Count
VAR_INPUT
    step : INT;
END_VAR
VAR_OUTPUT
    total : INT;
END_VAR
total := total + step;
END_FUNCTION_BLOCK
ST
tried=0
fail=0
expect() {  # FILE PATTERN
    if ! grep -q -- "$2" "$1"; then
        echo "$1: missing '$2'"; cat "$1"; fail=1
    fi
}
if command -v nvim >/dev/null 2>&1; then
    tried=1
    STRUN="$STRUN" OUT="$WORK/nvim.txt" timeout 60 nvim --headless -u "$HERE/nvim_init.lua" main.st -c "luafile $HERE/nvim_check.lua" </dev/null >/dev/null 2>&1
    touch nvim.txt
    expect nvim.txt "filetype iecst"
    expect nvim.txt "diagnostic 8:12 E0101 undeclared identifier 'missing'"
    expect nvim.txt "hover .*fb : FB_Count"
    expect nvim.txt "definition file://.*/fb.st:0"
else
    echo "nvim not installed: Neovim skipped"
fi
if command -v emacs >/dev/null 2>&1 && emacs --batch --eval "(progn (package-initialize) (require 'eglot))" >/dev/null 2>&1; then
    tried=1
    STRUN="$STRUN" OUT="$WORK/emacs.txt" timeout 90 emacs --batch -l "$HERE/eglot_check.el" </dev/null >/dev/null 2>&1
    touch emacs.txt
    expect emacs.txt "mode iec-st-mode"
    expect emacs.txt "diagnostic 8 .*undeclared identifier 'missing'"
    expect emacs.txt "hover .*fb : FB_Count"
    expect emacs.txt "definition file://.*/fb.st:0"
else
    echo "emacs with eglot not installed: Emacs skipped"
fi
[ "$tried" = 0 ] && exit 77
[ "$fail" = 0 ] && echo "editor set-ups: all checks passed"
exit "$fail"
