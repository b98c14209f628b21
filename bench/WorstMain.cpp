// gen_worst: writes the worst-case compile programs of gen/WorstPrograms.h as STL files, for
// timing them with the ladderjit driver (docs/BENCHMARKS.md "Compile time is linear").
#include "gen/WorstPrograms.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: gen_worst DIR STATEMENTS [NAME...]\n"
                         "writes DIR/NAME_STATEMENTS.stl for every worst case (or the NAMEs)\n");
    return 2;
  }
  const std::string dir = argv[1];
  const int n = std::atoi(argv[2]);
  std::vector<std::string> names;
  for (int k = 3; k < argc; ++k) names.emplace_back(argv[k]);
  if (names.empty()) names = lj::gen::worstCaseNames();
  for (const std::string &name : names) {
    lj::gen::GenProgram p = lj::gen::generateWorst(name, n);
    if (p.lines.empty()) {
      std::fprintf(stderr, "gen_worst: no worst case named %s\n", name.c_str());
      return 1;
    }
    const std::string path = dir + "/" + name + "_" + std::to_string(n) + ".stl";
    std::ofstream out(path);
    out << p.text() << '\n';
    if (!out) {
      std::fprintf(stderr, "gen_worst: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s\n", path.c_str());
  }
  return 0;
}
