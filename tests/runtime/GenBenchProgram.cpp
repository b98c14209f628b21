// Writes the benchmark program of docs/BENCHMARKS.md "Inputs" (gen/ProgramGenerator.h
// generateRealistic, seed 20240000 + size) to a file, for the serve evidence runs
// (docs/BENCHMARKS.md "serve"): `serve_bench_program SIZE OUT.stl [SEED]`.
#include "gen/ProgramGenerator.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
  if (argc < 3 || argc > 4) {
    std::fprintf(stderr, "usage: serve_bench_program SIZE OUT.stl [SEED]\n");
    return 2;
  }
  lj::gen::RealisticOptions o;
  o.statements = std::atoi(argv[1]);
  if (o.statements < 100 || o.statements > 10000) {
    std::fprintf(stderr, "serve_bench_program: SIZE must be 100..10000\n");
    return 2;
  }
  o.seed = argc == 4 ? std::strtoull(argv[3], nullptr, 10) : 20240000u + o.statements;
  std::ofstream out(argv[2], std::ios::trunc);
  if (!(out << lj::gen::generateRealistic(o).text() << "\n")) {
    std::fprintf(stderr, "serve_bench_program: cannot write '%s'\n", argv[2]);
    return 2;
  }
  return 0;
}
