#!/bin/sh
# The VS Code extension in CI: npm installs its packages into a copy of this
# folder (nothing is written into the source tree), TypeScript compiles the
# extension, vscode-tmgrammar-test checks the grammar on test/grammar/, and
# vsce packages a .vsix when asked (STRUN_VSIX=1). Exit 77 (ctest: skipped) without npm or
# when the npm registry cannot be reached.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
command -v npm >/dev/null 2>&1 || { echo "npm not installed: skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp -R "$here/package.json" "$here/tsconfig.json" "$here/language-configuration.json" \
      "$here/src" "$here/syntaxes" "$here/snippets" "$here/test" "$work/"
cd "$work"
if ! npm install --no-audit --no-fund --prefer-offline --loglevel=error >npm.log 2>&1; then
    if grep -qiE 'ENOTFOUND|EAI_AGAIN|ECONNREFUSED|ETIMEDOUT|network' npm.log; then
        echo "the npm registry cannot be reached: skipped"; cat npm.log; exit 77
    fi
    cat npm.log; exit 1
fi
npx --no-install tsc -p .
test -f out/extension.js
npx --no-install vscode-tmgrammar-test -g syntaxes/st.tmLanguage.json -g syntaxes/twincat.tmLanguage.json \
    "test/grammar/*.st" "test/grammar/*.TcPOU"
# A .vsix with STRUN_VSIX=1 (vsce is a large download of its own: not in every CI run).
if [ "${STRUN_VSIX:-0}" = 1 ] && npm install --no-audit --no-fund --loglevel=error --no-save @vscode/vsce >/dev/null 2>&1; then
    npx --no-install vsce package --no-dependencies --allow-missing-repository --skip-license >/dev/null 2>&1 \
        && ls ./*.vsix && echo "packaged" || echo "vsce could not package (not an error)"
fi
echo "vscode extension: compiled and grammar tested"
