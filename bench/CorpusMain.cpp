// gen_corpus: writes the shape corpus of gen/ShapeCorpus.h (seed 20330000 + shape index) into a
// directory, one file per shape (NAME.stl / .pmc / .il), for `ladderjit bench` and
// docs/BENCHMARKS.md "Shape corpus". `ladderjit bench --corpus` generates the same programs.
#include "gen/ShapeCorpus.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
  int n = argc == 3 ? std::atoi(argv[2]) : 10000;
  if (argc < 2 || argc > 3 || n < 40 || n > 1000000) {
    std::fprintf(stderr, "usage: gen_corpus OUTDIR [STATEMENTS]\nSTATEMENTS: 40..1000000 "
                         "(default 10000)\n");
    return 2;
  }
  const auto &shapes = lj::gen::corpusShapes();
  for (size_t i = 0; i < shapes.size(); ++i) {
    std::string path = std::string(argv[1]) + "/" + shapes[i].name + shapes[i].extension;
    std::ofstream out(path);
    out << lj::gen::generateShape(shapes[i].name, 20330000u + i, n).text() << '\n';
    if (!out) {
      std::fprintf(stderr, "gen_corpus: cannot write %s\n", path.c_str());
      return 1;
    }
    std::printf("%s\n", path.c_str());
  }
  return 0;
}
