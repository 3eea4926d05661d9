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
echo ok
