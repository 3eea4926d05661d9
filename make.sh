#!/bin/sh
# The README's entry point on a fresh Debian machine: installs `make` when it
# is missing, then runs the Makefile target (`run`, `test`, `bench`), which
# installs the rest of what the build needs.
set -e
cd "$(dirname "$0")"
if ! command -v make >/dev/null 2>&1; then
    SUDO=""
    [ "$(id -u)" -eq 0 ] || SUDO=sudo
    $SUDO apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq make
fi
exec make "$@"
