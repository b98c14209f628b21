#!/usr/bin/env bash
# The shape corpus regression check (docs/BENCHMARKS.md "Shape corpus"): runs
# `ladderjit bench --corpus --format json` (or reads a result already taken) and fails when a
# shape's jit-opt / best-C or aot / best-C ratio is more than 5% above the previous run recorded
# on the same machine. Not a unit test: it times code, so it runs on demand, on an idle machine.
#
#   scripts/bench-check.sh BUILD_DIR RECORDED.json [NEW.json]
#     BUILD_DIR      the build tree (its tools/ladderjit runs the corpus when NEW.json is absent)
#     RECORDED.json  the previous `bench --corpus --format json` of this machine
#     NEW.json       a result to check instead of running the corpus (written there otherwise)
# Exit 0: no shape regressed; 1: one did (named); 2: usage or bench error.
# BENCH_CHECK_TOLERANCE (default 0.05) and BENCH_CHECK_ARGS (extra bench flags) may be set.
set -euo pipefail
if [[ $# -lt 2 || $# -gt 3 ]]; then
  sed -n '2,12p' "$0" >&2
  exit 2
fi
build=$1 recorded=$2 new=${3:-}
[[ -f $recorded ]] || { echo "bench-check: no recorded result $recorded" >&2; exit 2; }
if [[ -z $new || ! -f $new ]]; then
  new=${new:-$(mktemp /tmp/bench-corpus-XXXXXX.json)}
  # shellcheck disable=SC2086
  "$build/tools/ladderjit" bench --corpus --format json ${BENCH_CHECK_ARGS:-} >"$new" 2>/dev/null ||
    { echo "bench-check: bench --corpus failed" >&2; exit 2; }
fi
python3 - "$recorded" "$new" "${BENCH_CHECK_TOLERANCE:-0.05}" <<'PY'
import json, sys
old, new, tol = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), float(sys.argv[3])
before = {s["name"]: s["ratios"] for s in old["shapes"]}
bad = 0
for s in new["shapes"]:
    for key, r in s["ratios"].items():
        b = before.get(s["name"], {}).get(key)
        if not b or not r:
            print(f"  {s['name']:14} {key:16} {r:.3f} (no previous)")
            continue
        verdict = "REGRESSED" if r > b * (1 + tol) else "ok"
        bad += verdict != "ok"
        print(f"  {s['name']:14} {key:16} {b:.3f} -> {r:.3f} ({(r / b - 1) * 100:+.1f}%) {verdict}")
print("bench-check:", "FAILED" if bad else "passed", f"({bad} regressed beyond {tol * 100:.0f}%)")
sys.exit(1 if bad else 0)
PY
