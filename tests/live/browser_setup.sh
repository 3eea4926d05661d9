#!/bin/sh
# Installs puppeteer-core (which drives the system's Chromium; it downloads
# no browser) into DIR for tests/live/browser_test.js. Nothing is committed:
# DIR is in the build directory.
set -e
DIR="$1"
VERSION=23.11.1   # the last line that runs on Node 18..20 (Debian's nodejs)
if [ -f "$DIR/node_modules/puppeteer-core/package.json" ] && grep -q "\"version\": \"$VERSION\"" "$DIR/node_modules/puppeteer-core/package.json"; then
  exit 0
fi
mkdir -p "$DIR"
PUPPETEER_SKIP_DOWNLOAD=1 npm install --prefix "$DIR" --no-audit --no-fund --no-save --loglevel=error "puppeteer-core@$VERSION"
