// The oracle harness's helper (tests/classicladder/clharness.py):
//   clp_tool info PROJECT         the project read, as one JSON line: the loadrt sizes the harness
//                                 gives classicladder_rt (the larger of general.txt and what the
//                                 rungs use), the warnings, or the located error;
//   clp_tool gen SEED OUT [RUNGS] a random project of gen/ClpGenerator written to OUT;
//   clp_tool ref PROJECT STIM OUT the reference scan (oracle/classicladder) run on the
//                                 harness's stimulus CSV, its trace written to OUT (the
//                                 harness's `--other` side).
//   clp_tool engine NAME PROJECT STIM OUT  the same with ladderjit's engine NAME (interp, jit,
//                                 aot): the project compiled by the classicladder front end,
//                                 one tick of 1 ms per stimulus row (the harness's `--other`
//                                 side, ladderjit against classicladder_rt itself).
#include "frontends/classicladder/Reader.h"
#include "gen/ClpGenerator.h"
#include "oracle/classicladder/RefScan.h"
#include "pipeline/Compile.h"
#include "pipeline/Dialects.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/Machine.h"

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

lj::oracle::ClSizes sizesOf(const Project &p) {
  auto rows = loadrt(p);
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
  return sz;
}

/// ladderjit's engine `name` as the harness's other side (the format of ref() below).
int engine(const std::string &name, const std::string &path, const std::string &stimulus,
           const std::string &trace) {
  auto r = readProject(path);
  if (!r.ok()) {
    std::cerr << r.status().message() << "\n";
    return 1;
  }
  const lj::oracle::ClSizes sz = sizesOf(*r);
  std::ifstream src(path, std::ios::binary);
  std::stringstream text;
  text << src.rdbuf();
  lj::Diagnostics diags(path);
  std::optional<lj::VerifiedProgram> prog =
      lj::pipeline::compileClp(text.str(), path, lj::VerifyOptions{}, diags);
  if (!prog) {
    std::cerr << diags.render();
    return 1;
  }
  std::unique_ptr<lj::test::Machine> m;
  for (const lj::test::EngineFactory &f : lj::test::registeredEngines())
    if (f.name == name) m = lj::test::Machine::create(*prog, f);
  if (!m) {
    std::cerr << "no engine '" << name << "' (interp, jit, aot)\n";
    return 1;
  }
  m->init();
  const lj::pipeline::Dialect *d = lj::pipeline::dialectNamed("classicladder");
  auto addr = [&](const std::string &t) {
    std::string err;
    return d->parseAddress(t, err).value();
  };
  std::vector<lj::formats::CliAddress> in, out;
  for (int i = 0; i < sz.inputs; ++i) in.push_back(addr("%I" + std::to_string(i)));
  for (int i = 0; i < sz.s32in; ++i) in.push_back(addr("%IW" + std::to_string(i)));
  for (int i = 0; i < sz.floatIn; ++i) in.push_back(addr("%IF" + std::to_string(i)));
  for (int i = 0; i < sz.outputs; ++i) out.push_back(addr("%Q" + std::to_string(i)));
  for (int i = 0; i < sz.s32out; ++i) out.push_back(addr("%QW" + std::to_string(i)));
  for (int i = 0; i < sz.floatOut; ++i) out.push_back(addr("%QF" + std::to_string(i)));
  std::ifstream inf(stimulus);
  std::ofstream outf(trace);
  std::string line;
  std::getline(inf, line);
  outf << "period";
  for (int i = 0; i < sz.outputs; ++i) outf << ",out-" << (i < 10 ? "0" : "") << i;
  for (int i = 0; i < sz.s32out; ++i) outf << ",s32out-" << (i < 10 ? "0" : "") << i;
  for (int i = 0; i < sz.floatOut; ++i) outf << ",floatout-" << (i < 10 ? "0" : "") << i;
  outf << "\n";
  const size_t fin = static_cast<size_t>(sz.inputs + sz.s32in);
  while (std::getline(inf, line)) {
    auto c = cells(line);
    if (c.size() != 1 + in.size()) {
      std::cerr << stimulus << ": a row of " << c.size() << " cells\n";
      return 1;
    }
    for (size_t k = 0; k < in.size(); ++k) {
      // floatin-NN: 2.9 reads it as int (truncated toward zero), so the host writes that
      const int64_t v = k >= fin ? static_cast<int64_t>(std::strtod(c[k + 1].c_str(), nullptr))
                                 : std::strtoll(c[k + 1].c_str(), nullptr, 10);
      lj::formats::writeAddress(m->state(), in[k], k < static_cast<size_t>(sz.inputs) ? v != 0 : v);
    }
    if (m->tick() != LJ_FAULT_NONE) {
      std::cerr << "period " << c[0] << ": fault\n";
      return 1;
    }
    outf << c[0];
    char b[64];
    for (size_t j = 0; j < out.size(); ++j) {
      const int64_t v = lj::formats::readAddress(m->state(), out[j]);
      if (j >= static_cast<size_t>(sz.outputs + sz.s32out)) {
        std::snprintf(b, sizeof b, ",%.6f", static_cast<double>(static_cast<int32_t>(v)));
        outf << b;
      } else {
        outf << "," << static_cast<int32_t>(v);
      }
    }
    outf << "\n";
  }
  return 0;
}

/// The reference scan as the harness's other side: stimulus CSV in, trace CSV out.
int ref(const std::string &path, const std::string &stimulus, const std::string &trace) {
  auto r = readProject(path);
  if (!r.ok()) {
    std::cerr << r.status().message() << "\n";
    return 1;
  }
  const lj::oracle::ClSizes sz = sizesOf(*r);
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
  if (cmd == "engine" && argc == 6) return engine(argv[2], argv[3], argv[4], argv[5]);
  if (cmd == "gen" && (argc == 4 || argc == 5)) {
    uint64_t seed = std::strtoull(argv[2], nullptr, 10);
    int rungs = argc == 5 ? std::atoi(argv[4]) : 8;
    std::ofstream(argv[3], std::ios::binary) << lj::gen::generateClp(seed, rungs);
    return 0;
  }
  std::cerr
      << "usage: clp_tool info PROJECT | clp_tool gen SEED OUT.clp [RUNGS] | clp_tool ref "
         "PROJECT STIMULUS.csv TRACE.csv | clp_tool engine interp|jit|aot PROJECT STIMULUS.csv "
         "TRACE.csv\n";
  return 2;
}
