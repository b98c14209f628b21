#!/bin/bash
# Evidence run for docs/BENCHMARKS.md "serve": online change of the 10k program under load.
# Not a CTest test (it runs 60 s at real-time priority). Usage:
#   tests/runtime/serve_swap_evidence.sh BUILD_DIR WORK_DIR
set -eu
B=$1
W=$2
LJ=$B/tools/ladderjit
mkdir -p "$W"
cd "$W"
"$B/tests/runtime/serve_bench_program" 10000 p10k.stl
"$B/tests/runtime/serve_bench_program" 10000 p10k_b.stl 777
S=$W/c.sock
"$LJ" serve p10k.stl --duration 60 --rt-priority 80 --stats swap.json --control "$S" >swap.out 2>&1 &
PID=$!
until [ -S "$S" ]; do sleep 0.1; done
"$LJ" monitor --control "$S" write B7=4242
stats() {
  "$LJ" monitor --control "$S" stats | python3 -c \
    'import json,sys; j=json.load(sys.stdin); print(j["missed_deadlines"], j["overruns"], j["ticks"])'
}
for i in 1 2 3 4 5 6; do
  sleep 5
  before=$(stats)
  if [ $((i % 2)) = 1 ]; then P=p10k_b.stl; else P=p10k.stl; fi
  "$LJ" monitor --control "$S" load $P
  echo "swap $i -> $P: (missed overruns ticks) before=$before after=$(stats);" \
    "$("$LJ" monitor --control "$S" read B7)"
done
wait $PID
cat swap.out
