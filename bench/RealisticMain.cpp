// gen_realistic: writes the realistic benchmark program of bench/BenchPrograms.h (seed
// 20240000 + N) as an STL file, for `ladderjit bench` (docs/BENCHMARKS.md). `--core` writes the
// C-baseline variant (gen::RealisticOptions::coreSubset) instead.
#include "gen/ProgramGenerator.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
  bool core = argc == 4 && std::strcmp(argv[3], "--core") == 0;
  int n = argc >= 3 ? std::atoi(argv[1]) : 0;
  if ((argc != 3 && !core) || n < 40 || n > 1000000) {
    std::fprintf(stderr, "usage: gen_realistic STATEMENTS OUT.stl [--core]\n"
                         "STATEMENTS: 40..1000000; --core: only the C baseline's subset\n");
    return 2;
  }
  lj::gen::RealisticOptions o;
  o.seed = 20240000u + static_cast<uint64_t>(n);
  o.statements = n;
  o.coreSubset = core;
  std::ofstream out(argv[2]);
  out << lj::gen::generateRealistic(o).text() << '\n';
  if (!out) {
    std::fprintf(stderr, "gen_realistic: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}
