// gen-instr-doc: prints docs/instructions.md (the instruction reference) from the instruction
// table and instructions/InstrDocs.cpp; `-o FILE` writes it to a file instead.
#include "frontends/hnc8/InstrDocs.h"

#include <cstring>
#include <fstream>
#include <iostream>

int main(int argc, char **argv) {
  const std::string text = lj::renderInstructionReference();
  if (argc == 1) {
    std::cout << text;
    return 0;
  }
  if (argc == 3 && std::strcmp(argv[1], "-o") == 0) {
    std::ofstream out(argv[2], std::ios::binary);
    out << text;
    if (out.good()) return 0;
    std::cerr << "gen-instr-doc: cannot write '" << argv[2] << "'\n";
    return 2;
  }
  std::cerr << "usage: gen-instr-doc [-o FILE]\n";
  return 2;
}
