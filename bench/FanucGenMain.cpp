// gen_fanuc: writes a FANUC PMC program of about STATEMENTS lines from the differential fuzzer's
// generator (gen/FanucProgram.h, seed 20250000 + N unless given) as a .pmc file, for
// `ladderjit bench` at a realistic program size (docs/BENCHMARKS.md "FANUC and IEC").
#include "gen/FanucProgram.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
  int n = argc >= 3 ? std::atoi(argv[1]) : 0;
  if ((argc != 3 && argc != 4) || n < 10 || n > 1000000) {
    std::fprintf(stderr, "usage: gen_fanuc STATEMENTS OUT.pmc [SEED]\nSTATEMENTS: 10..1000000\n");
    return 2;
  }
  uint64_t seed = argc == 4 ? std::strtoull(argv[3], nullptr, 10) : 20250000u + uint64_t(n);
  std::ofstream out(argv[2]);
  for (const std::string &line : lj::gen::generateFanuc(seed, n)) out << line << '\n';
  if (!out) {
    std::fprintf(stderr, "gen_fanuc: cannot write %s\n", argv[2]);
    return 1;
  }
  return 0;
}
