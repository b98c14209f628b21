#!/usr/bin/env bash
# Draw the manual's ORB/ANB/MPS examples and examples/lathe_panel.stl as HTML and screenshot them
# in headless Chromium (scripts/setup-test.sh installs it) into docs/images/. Usage:
#   scripts/ladder-screenshots.sh [build/tools/ladderjit]
set -euo pipefail
cd "$(dirname "$0")/.."
exe=${1:-build/tools/ladderjit}
out=docs/images
tmp=$(mktemp -d)
shot() { # html png width height [fragment]
  chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size="$3,$4" \
    --screenshot="$2" "file://$1${5:-}" >/dev/null 2>&1
}
for f in orb anb mps1 mps2 mps3 boxes stl-rung; do
  "$exe" ladder "$out/ladder-src/$f.stl" --format html -o "$tmp/$f.html"
  shot "$tmp/$f.html" "$out/ladder-$f.png" 900 "$([[ $f == boxes ]] && echo 1150 || echo 520)"
done
"$exe" ladder examples/lathe_panel.stl --format html -o "$tmp/lathe.html"
shot "$tmp/lathe.html" "$out/ladder-lathe_panel-init.png" 1000 520
shot "$tmp/lathe.html" "$out/ladder-lathe_panel-plc1.png" 1000 1700 "#part-1"
rm -rf "$tmp"
