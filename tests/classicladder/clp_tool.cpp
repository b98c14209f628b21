// The oracle harness's helper (tests/classicladder/clharness.py):
//   clp_tool info PROJECT         the project read, as one JSON line: the loadrt sizes the harness
//                                 gives classicladder_rt (the larger of general.txt and what the
//                                 rungs use), the warnings, or the located error;
//   clp_tool gen SEED OUT [RUNGS] a random project of gen/ClpGenerator written to OUT;
//   clp_tool ref PROJECT STIM OUT the reference scan (oracle/classicladder) run on the
//                                 harness's stimulus CSV, its trace written to OUT (the
//                                 harness's `--other` side).
#include "frontends/classicladder/Reader.h"
#include "gen/ClpGenerator.h"
#include "oracle/classicladder/RefScan.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

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

struct Row {
  const char *param;
  int value;
};

/// The loadrt parameters for a project: the larger of general.txt and what the rungs use.
std::vector<Row> loadrt(const Project &p) {
  const Sizes &s = p.sizes, &n = p.needed;
  int maxRung = p.rungs.empty() ? 0 : p.rungs.rbegin()->first + 1;
  int sections = 0;
  for (const auto &sec : p.sections) sections = std::max(sections, sec.number + 1);
  std::vector<Row> rows = {{"numRungs", std::max(s.rungs, maxRung)},
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
  for (auto &r : rows) r.value = std::max(r.value, 1);
  return rows;
}

int get(const std::vector<Row> &rows, const std::string &name) {
  for (const auto &r : rows)
    if (name == r.param) return r.value;
  return 1;
}

int info(const std::string &path) {
  auto r = readProject(path);
  if (!r.ok()) {
    std::cout << "{\"ok\":false,\"error\":" << quote(r.status().message()) << "}\n";
    return 0;
  }
  const Project &p = *r;
  auto rows = loadrt(p);
  bool seq = false;
  for (const auto &sec : p.sections) seq |= sec.language == Language::Sequential;
  std::cout << "{\"ok\":true,\"loadrt\":{";
  for (size_t i = 0; i < rows.size(); ++i)
    std::cout << (i ? "," : "") << quote(rows[i].param) << ":" << rows[i].value;
  std::cout << "},\"rungs\":" << p.rungs.size() << ",\"sections\":" << p.sections.size()
            << ",\"sequential\":" << (seq ? "true" : "false")
            << ",\"upstream\":" << (p.flavor == Flavor::Upstream09 ? "true" : "false")
            << ",\"warnings\":[";
  for (size_t i = 0; i < p.warnings.size(); ++i)
    std::cout << (i ? "," : "") << quote(p.warnings[i]);
  std::cout << "]}\n";
  return 0;
}

std::vector<std::string> cells(const std::string &line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string c;
  while (std::getline(ss, c, ',')) out.push_back(c);
  return out;
}

/// The reference scan as the harness's other side: stimulus CSV in, trace CSV out.
int ref(const std::string &path, const std::string &stimulus, const std::string &trace) {
  auto r = readProject(path);
  if (!r.ok()) {
    std::cerr << r.status().message() << "\n";
    return 1;
  }
  auto rows = loadrt(*r);
  lj::oracle::ClSizes sz;
  sz.bits = get(rows, "numBits");
  sz.words = get(rows, "numWords");
  sz.timers = get(rows, "numTimers");
  sz.monostables = get(rows, "numMonostables");
  sz.counters = get(rows, "numCounters");
  sz.timersIec = get(rows, "numTimersIec");
  sz.inputs = get(rows, "numPhysInputs");
  sz.outputs = get(rows, "numPhysOutputs");
  sz.s32in = get(rows, "numS32in");
  sz.s32out = get(rows, "numS32out");
  sz.floatIn = get(rows, "numFloatIn");
  sz.floatOut = get(rows, "numFloatOut");
  lj::oracle::ClReferenceScan scan(*r, sz);
  std::ifstream in(stimulus);
  std::ofstream out(trace);
  std::string line;
  std::getline(in, line); // header: period, in-NN..., s32in-NN..., floatin-NN...
  out << "period";
  for (int i = 0; i < sz.outputs; ++i) out << ",out-" << (i < 10 ? "0" : "") << i;
  for (int i = 0; i < sz.s32out; ++i) out << ",s32out-" << (i < 10 ? "0" : "") << i;
  for (int i = 0; i < sz.floatOut; ++i) out << ",floatout-" << (i < 10 ? "0" : "") << i;
  out << "\n";
  while (std::getline(in, line)) {
    auto c = cells(line);
    if (c.size() != static_cast<size_t>(1 + sz.inputs + sz.s32in + sz.floatIn)) {
      std::cerr << stimulus << ": a row of " << c.size() << " cells\n";
      return 1;
    }
    size_t k = 1;
    for (auto &v : scan.in) v = std::atoi(c[k++].c_str()) != 0;
    for (auto &v : scan.s32in) v = static_cast<int32_t>(std::strtol(c[k++].c_str(), nullptr, 10));
    for (auto &v : scan.floatIn) v = std::strtod(c[k++].c_str(), nullptr);
    scan.refresh(1);
    out << c[0];
    for (auto v : scan.out) out << "," << int(v);
    for (auto v : scan.s32out) out << "," << v;
    char b[64];
    for (auto v : scan.floatOut) {
      std::snprintf(b, sizeof b, ",%.6f", v);
      out << b;
    }
    out << "\n";
  }
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  std::string cmd = argc > 1 ? argv[1] : "";
  if (cmd == "info" && argc == 3) return info(argv[2]);
  if (cmd == "ref" && argc == 5) return ref(argv[2], argv[3], argv[4]);
  if (cmd == "gen" && (argc == 4 || argc == 5)) {
    uint64_t seed = std::strtoull(argv[2], nullptr, 10);
    int rungs = argc == 5 ? std::atoi(argv[4]) : 8;
    std::ofstream(argv[3], std::ios::binary) << lj::gen::generateClp(seed, rungs);
    return 0;
  }
  std::cerr << "usage: clp_tool info PROJECT | clp_tool gen SEED OUT.clp [RUNGS] | clp_tool ref "
               "PROJECT STIMULUS.csv TRACE.csv\n";
  return 2;
}
