#!/bin/sh
# `cmake --install` puts strun and its documentation in place, and the
# installed strun reports the project's version.
# usage: install_check.sh CMAKE BUILD_DIR VERSION
cmake=$1
build=$2
version=$3
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
"$cmake" --install "$build" --prefix "$prefix" >/dev/null || { echo "cmake --install failed"; exit 1; }
[ "$("$prefix/bin/strun" --version)" = "strun $version" ] || { echo "installed strun --version is not 'strun $version'"; exit 1; }
[ -f "$prefix/share/doc/strun/cli.md" ] || { echo "docs/cli.md not installed"; exit 1; }
[ -f "$prefix/share/doc/strun/README.md" ] || { echo "README.md not installed"; exit 1; }
[ -f "$prefix/share/doc/strun/examples/tank_stimulus.csv" ] || { echo "examples not installed"; exit 1; }
[ -f "$prefix/share/man/man1/strun.1" ] || { echo "man page strun.1 not installed"; exit 1; }
grep -q '^\.TH STRUN 1' "$prefix/share/man/man1/strun.1" || { echo "strun.1 is not a man page"; exit 1; }
grep -q 'allow\\-empty' "$prefix/share/man/man1/strun.1" || { echo "strun.1 lacks the options of strun test"; exit 1; }
# The installed docs name installed paths, not those of a checkout (issue 29).
if grep -l 'build/strun' "$prefix/share/doc/strun"/*.md; then echo "installed docs still say build/strun"; exit 1; fi
grep -q "$prefix/share/doc/strun/cli.md" "$prefix/share/doc/strun/README.md" || { echo "installed README does not point at the installed cli.md"; exit 1; }
grep -q "$prefix/share/doc/strun/examples/" "$prefix/share/doc/strun/README.md" || { echo "installed README does not point at the installed examples"; exit 1; }
echo ok
