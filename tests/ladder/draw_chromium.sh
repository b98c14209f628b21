#!/usr/bin/env bash
# The HTML drawing in a real browser (headless Chromium from scripts/setup-test.sh): the page's
# script ran (the first tab is selected), every rung of the layout is in the DOM with its
# data-stmt elements, and a screenshot is kept in OUT. Fails without Chromium: the test command installs it.
set -euo pipefail
exe=$1 program=$2 out=$3
command -v chromium >/dev/null 2>&1 || { echo "chromium not installed: run scripts/setup-test.sh" >&2; exit 1; }
mkdir -p "$out"
"$exe" ladder "$program" --format html -o "$out/page.html"
want=$("$exe" ladder "$program" --format layout | python3 -c \
  'import json,sys; print(sum(len(p["rungs"]) for p in json.load(sys.stdin)["parts"]))')
dom=$(timeout 60 chromium --headless --no-sandbox --disable-gpu --virtual-time-budget=1000 \
  --dump-dom "file://$out/page.html" 2>/dev/null)
rungs=$(grep -o 'class="rung"' <<<"$dom" | wc -l)
selected=$(grep -o 'class="tab sel"' <<<"$dom" | wc -l)
stmts=$(grep -o 'data-stmt="' <<<"$dom" | wc -l)
timeout 60 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1000,900 \
  --screenshot="$out/page.png" "file://$out/page.html" >/dev/null 2>&1
size=$(stat -c %s "$out/page.png" 2>/dev/null || echo 0)
echo "rungs in DOM $rungs (layout $want), selected tabs $selected, data-stmt elements $stmts, screenshot $size bytes"
[[ $rungs -eq $want && $selected -eq 1 && $stmts -gt 0 && $size -gt 5000 ]]
