// The oracle harness's helper (tests/classicladder/clharness.py):
//   clp_tool info PROJECT         the project read, as one JSON line: the loadrt sizes the harness
//                                 gives classicladder_rt (the larger of general.txt and what the
//                                 rungs use), the warnings, or the located error;
//   clp_tool gen SEED OUT [RUNGS] a random project of gen/ClpGenerator written to OUT.
#include "frontends/classicladder/Reader.h"
#include "gen/ClpGenerator.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

using namespace lj::classicladder;

namespace {

std::string quote(const std::string &s) {
  std::string o = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\')
      o += '\\', o += static_cast<char>(c);
    else if (c < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      o += b;
    } else
      o += static_cast<char>(c);
  }
  return o + "\"";
}

int info(const std::string &path) {
  auto r = readProject(path);
  if (!r.ok()) {
    std::cout << "{\"ok\":false,\"error\":" << quote(r.status().message()) << "}\n";
    return 0;
  }
  const Project &p = *r;
  const Sizes &s = p.sizes, &n = p.needed;
  int maxRung = p.rungs.empty() ? 0 : p.rungs.rbegin()->first + 1;
  int sections = 0;
  for (const auto &sec : p.sections) sections = std::max(sections, sec.number + 1);
  struct Row {
    const char *param;
    int value;
  } rows[] = {{"numRungs", std::max(s.rungs, maxRung)},
              {"numBits", std::max(s.bits, n.bits)},
              {"numWords", std::max(s.words, n.words)},
              {"numTimers", std::max(s.timers, n.timers)},
              {"numMonostables", std::max(s.monostables, n.monostables)},
              {"numCounters", std::max(s.counters, n.counters)},
              {"numTimersIec", std::max(s.timersIec, n.timersIec)},
              {"numPhysInputs", std::max(s.physInputs, n.physInputs)},
              {"numPhysOutputs", std::max(s.physOutputs, n.physOutputs)},
              {"numArithmExpr", std::max(s.arithmExpr, n.arithmExpr)},
              {"numSections", std::max(s.sections, sections)},
              {"numS32in", std::max(s.s32in, n.s32in)},
              {"numS32out", std::max(s.s32out, n.s32out)},
              {"numFloatIn", std::max(s.floatIn, n.floatIn)},
              {"numFloatOut", std::max(s.floatOut, n.floatOut)}};
  bool seq = false;
  for (const auto &sec : p.sections) seq |= sec.language == Language::Sequential;
  std::cout << "{\"ok\":true,\"loadrt\":{";
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; ++i)
    std::cout << (i ? "," : "") << quote(rows[i].param) << ":" << std::max(rows[i].value, 1);
  std::cout << "},\"rungs\":" << p.rungs.size() << ",\"sections\":" << p.sections.size()
            << ",\"sequential\":" << (seq ? "true" : "false")
            << ",\"upstream\":" << (p.flavor == Flavor::Upstream09 ? "true" : "false")
            << ",\"warnings\":[";
  for (size_t i = 0; i < p.warnings.size(); ++i)
    std::cout << (i ? "," : "") << quote(p.warnings[i]);
  std::cout << "]}\n";
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  if (cmd == "info" && argc == 3) return info(argv[2]);
  if (cmd == "gen" && (argc == 4 || argc == 5)) {
    uint64_t seed = std::strtoull(argv[2], nullptr, 10);
    int rungs = argc == 5 ? std::atoi(argv[4]) : 8;
    std::ofstream(argv[3], std::ios::binary) << lj::gen::generateClp(seed, rungs);
    return 0;
  }
  std::cerr << "usage: clp_tool info PROJECT | clp_tool gen SEED OUT.clp [RUNGS]\n";
  return 2;
}
