# Sourced by the sandbox tests: a temporary directory with the sandbox `box`
# and a directory `outside` holding secret.txt, reached from the box through
# two symbolic links (box/link -> ../outside, box/secret.txt -> the file).
# Leaves $tmp set and removes it on exit; fail MESSAGE prints the dump.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/box" "$tmp/outside"
echo secret > "$tmp/outside/secret.txt"
ln -s ../outside "$tmp/box/link"
ln -s ../outside/secret.txt "$tmp/box/secret.txt"
fail() { echo "FAIL: $1"; cat "$tmp/dump.json"; exit 1; }
