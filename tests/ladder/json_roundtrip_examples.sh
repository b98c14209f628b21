#!/bin/sh
# Every example through `ladderjit ladder --format json` and back: `ladderjit run` on the .stl and
# on its JSON must print the same watch table (every tick) and dump the same final state, on the
# interpreter and the JIT. Usage: json_roundtrip_examples.sh LADDERJIT EXAMPLES_DIR WORK_DIR
set -eu
lj=$1 ex=$2 work=$3
mkdir -p "$work"
watch="Y0,Y1,Y2,Y480,Y481,R0,R1,R5,R10,R20,R30,R32,R300,R304,G2564,G2620,G2622,G3010,D10,D11,D12,D40,D41,B0,C5,C6,T2,T11,W0"
n=0
for stl in "$ex"/*.stl; do
  name=$(basename "$stl" .stl)
  "$lj" ladder "$stl" --format json -o "$work/$name.json"
  set -- --ticks 100 --watch "$watch"
  [ -f "$ex/$name.stim" ] && set -- "$@" --stimulus "$ex/$name.stim"
  [ -f "$ex/$name.params" ] && set -- "$@" --params "$ex/$name.params"
  for engine in interp jit; do
    "$lj" run "$stl" --engine $engine "$@" --dump "$work/$name.stl.dump" > "$work/$name.stl.out"
    "$lj" run "$work/$name.json" --engine $engine "$@" --dump "$work/$name.json.dump" \
      > "$work/$name.json.out"
    cmp "$work/$name.stl.out" "$work/$name.json.out"
    cmp "$work/$name.stl.dump" "$work/$name.json.dump"
    [ "$(wc -l < "$work/$name.stl.out")" -eq 101 ] # header + 100 ticks: the table is really there
  done
  n=$((n + 1))
done
[ "$n" -ge 6 ]
echo "json round trip: $n examples, identical watch tables and dumps on interp and jit"
