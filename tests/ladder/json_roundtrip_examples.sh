#!/bin/sh
# Every example through `ladderjit ladder --format json` and back: `ladderjit run` on the program
# and on its JSON must print the same watch table (every tick) and dump the same final state, on the
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
# FANUC and IEC programs: their JSON carries the program text ("source") and is read back through
# it once its networks are checked against it (docs/ladder-json.md "Other dialects"); the AOT
# .so built from the .pmc / .il is accepted for the JSON too (same program hash).
m=0
for prog in "$ex"/*.pmc "$ex"/*.il; do
  file=$(basename "$prog")
  name=${file%.*}
  case "$file" in
  *.pmc) watch="X0,Y0,Y1,Y2,R0,R1,R10,R20,D0,D10,G4" ;;
  *) watch="%Q0.0,%Q0.1,%Q0.2,%Q0.3,%M0,%M10,%MW0,%MW10" ;;
  esac
  "$lj" ladder "$prog" --format json -o "$work/$file.json"
  grep -q '"source": ' "$work/$file.json"
  "$lj" compile "$prog" -o "$work/$file.so"
  set -- --ticks 300 --watch "$watch"
  [ -f "$ex/$name.stim" ] && set -- "$@" --stimulus "$ex/$name.stim"
  for engine in interp jit "aot:$work/$file.so"; do
    "$lj" run "$prog" --engine $engine "$@" --dump "$work/$file.dump" > "$work/$file.out" 2>/dev/null
    "$lj" run "$work/$file.json" --engine $engine "$@" --dump "$work/$file.json.dump" \
      > "$work/$file.json.out" 2>/dev/null
    cmp "$work/$file.out" "$work/$file.json.out"
    cmp "$work/$file.dump" "$work/$file.json.dump"
    [ "$(wc -l < "$work/$file.out")" -eq 301 ]
  done
  m=$((m + 1))
done
[ "$m" -ge 5 ]
echo "json round trip: $n HNC-8 examples, $m FANUC/IEC examples, identical watch tables and dumps"
