#!/bin/bash
# Online change latency as serve reports it (docs/BENCHMARKS.md "Online change"): serve the
# realistic 10k program, wait for the optimizing JIT, then CHANGES times `monitor load` a copy
# with one contact edited (a different rung each time, as bench_online_change edits), one
# second apart, and print `monitor stats`' "online_changes" (latency per change, the median).
# Not a CTest test (timing). Usage:
#   bench/OnlineChangeServe.sh BUILD_DIR WORK_DIR [CHANGES]
set -eu
B=$(cd "$1" && pwd)
W=$2
N=${3:-20}
LJ=$B/tools/ladderjit
mkdir -p "$W"
cd "$W"
"$B/bench/gen_realistic" 10000 p10k.stl >/dev/null
# The edited copies, written (and aged past the 500 ms settle interval) before the run.
python3 - "$N" <<'PY'
import sys
n = int(sys.argv[1])
lines = open("p10k.stl").read().split("\n")
sites = [i for i, l in enumerate(lines)
         if l.split(" ")[0] in ("LD", "LDI", "AND", "ANI", "OR", "ORI")
         and len(l.split(" ")) > 1 and l.split(" ")[1].startswith("X") and "." in l]
for c in range(1, n + 1):
    i = sites[(c * 7919 * len(sites) // 20011 + c) % len(sites)]
    l = lines[i]
    d = l.index(".")
    lines[i] = l[:d + 1] + ("0" if l[d + 1] == "7" else chr(ord(l[d + 1]) + 1)) + l[d + 2:]
    open("p10k_e%d.stl" % c, "w").write("\n".join(lines))
PY
sleep 1
S=$W/c.sock
rm -f "$S"
"$LJ" serve p10k.stl --duration 600 --stats online.json --control "$S" --load-dir "$W" \
  >serve.out 2>&1 &
PID=$!
until [ -S "$S" ]; do sleep 0.1; done
engine() {
  "$LJ" monitor --control "$S" stats |
    python3 -c 'import json,sys; print(json.load(sys.stdin)["startup"]["tiering"]["engine"])'
}
until [ "$(engine)" = jit-opt ]; do sleep 0.5; done
echo "serving on jit-opt; load average: $(cut -d' ' -f1-3 /proc/loadavg)"
for c in $(seq 1 "$N"); do
  "$LJ" monitor --control "$S" load "p10k_e$c.stl" >/dev/null
  sleep 1
done
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
"$LJ" monitor --control "$S" stats | python3 -c '
import json, sys
j = json.load(sys.stdin)["online_changes"]
print("%-7s %6s %9s %11s %9s %9s %9s %8s %11s %13s" % ("version", "tick", "engine", "latency_ms",
      "frontend", "build", "build_cpu", "swap", "groups", "optimized_ms"))
for c in j["recent"]:
    print("%-7d %6d %9s %11.2f %9.2f %9.2f %9.2f %8.2f %5d/%-5d %13.1f" % (c["version"], c["tick"],
          c["engine"], c["latency_ms"], c["frontend_ms"], c["build_ms"], c["build_cpu_ms"],
          c["swap_wait_ms"], c["groups_compiled"], c["groups"], c["optimized_ms"]))
l = j["latency_ms"]
print("online changes %d: latency (requested -> new code running) min %.2f / median %.2f / "
      "max %.2f ms (last %d)" % (j["count"], l["min"], l["median"], l["max"], l["of_last"]))'
"$LJ" monitor --control "$S" stop >/dev/null
wait $PID || true
grep -i "refused\|failed" serve.out || true
