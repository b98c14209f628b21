// The bounded differential campaign CTest runs: interpreter against the JIT (mixed tiers) on a
// few thousand small random programs; exit status 1 on any mismatch, engine error or program
// that does not verify. `difffuzz_campaign [--seed S] [--programs N] [--ticks T]
// [--statements K] [--tier mixed|fast|optimizing] [--switch 1]` (`--switch 1`: engine switches at
// random ticks against an unswitched interpreter run, fuzz/Fuzz.h FuzzOptions::switches).
#include "fuzz/Fuzz.h"

#include <cstdlib>
#include <cstring>
#include <iostream>

int main(int argc, char **argv) {
  lj::fuzz::FuzzOptions o;
  o.seed = 20250101;
  o.programs = 3000;
  o.ticks = 20;
  o.statements = 40;
  for (int i = 1; i + 1 < argc; i += 2) {
    const char *k = argv[i], *v = argv[i + 1];
    if (!std::strcmp(k, "--seed"))
      o.seed = std::strtoull(v, nullptr, 10);
    else if (!std::strcmp(k, "--programs"))
      o.programs = std::strtoull(v, nullptr, 10);
    else if (!std::strcmp(k, "--ticks"))
      o.ticks = static_cast<uint32_t>(std::atoi(v));
    else if (!std::strcmp(k, "--statements"))
      o.statements = std::atoi(v);
    else if (!std::strcmp(k, "--tier"))
      o.tiers = !std::strcmp(v, "fast")         ? lj::fuzz::TierMode::Fast
                : !std::strcmp(v, "optimizing") ? lj::fuzz::TierMode::Optimizing
                                                : lj::fuzz::TierMode::Mixed;
    else if (!std::strcmp(k, "--switch"))
      o.switches = std::strcmp(v, "0") != 0;
    else {
      std::cerr << "difffuzz_campaign: unknown option " << k << "\n";
      return 2;
    }
  }
  return lj::fuzz::run(o, std::cout) == 0 ? 0 : 1;
}
