// The report of `ladderjit bench` (docs/bench.md): scan statistics, the same-run ratios, and the
// text and JSON ("ladderjit-bench 1") forms.
#include "tools/ladderjit/BenchCmd.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <sstream>

namespace lj::cli::bench {

Stats statsOf(std::vector<double> v) {
  Stats st;
  if (v.empty()) return st;
  std::sort(v.begin(), v.end());
  st.minNs = v.front();
  st.medianNs = v[v.size() / 2];
  st.p99Ns = v[std::min(v.size() - 1, static_cast<size_t>(static_cast<double>(v.size()) * 0.99))];
  double sum = 0;
  for (double x : v) sum += x;
  st.meanNs = sum / static_cast<double>(v.size());
  return st;
}

namespace {

std::string fmtUs(double us) {
  char b[32];
  if (us >= 100000)
    std::snprintf(b, sizeof b, "%.0f ms", us / 1000);
  else if (us >= 1000)
    std::snprintf(b, sizeof b, "%.1f ms", us / 1000);
  else
    std::snprintf(b, sizeof b, "%.3f ms", us / 1000);
  return b;
}

std::string fmtNs(double ns) {
  char b[32];
  if (ns >= 100000)
    std::snprintf(b, sizeof b, "%.0f us", ns / 1000);
  else
    std::snprintf(b, sizeof b, "%.3f us", ns / 1000);
  return b;
}

} // namespace

std::vector<Ratio> ratiosOf(const std::vector<Lane> &lanes, const std::vector<Stats> &st) {
  auto find = [&](const std::string &n) -> int {
    for (size_t i = 0; i < lanes.size(); ++i)
      if (lanes[i].name == n) return static_cast<int>(i);
    return -1;
  };
  std::vector<Ratio> r;
  auto add = [&](const std::string &a, const std::string &b) {
    int i = find(a), j = find(b);
    if (i < 0 || j < 0 || st[static_cast<size_t>(j)].medianNs <= 0) return;
    r.push_back(
        {a + "/" + b, st[static_cast<size_t>(i)].medianNs / st[static_cast<size_t>(j)].medianNs});
  };
  add("jit-fast", "interp");
  add("jit-opt", "interp");
  add("aot", "interp");
  add("jit-opt", "jit-fast");
  add("aot", "jit-opt");
  for (const Lane &l : lanes)
    if (l.engine == "c") add("jit-opt", l.name), add("aot", l.name);
  return r;
}

namespace {

nlohmann::json phasesJson(const Phases &p) {
  nlohmann::json j;
  j["lower_us"] = p.lowerUs;
  j["optimize_us"] = p.optimizeUs;
  j["codegen_us"] = p.codegenUs;
  j["link_us"] = p.linkUs;
  j["cache_us"] = p.cacheUs;
  j["load_us"] = p.loadUs;
  j["total_us"] = p.totalUs;
  j["code_bytes"] = p.codeBytes;
  j["cache_hit"] = p.cacheHit;
  return j;
}

} // namespace

void printText(const BenchArgs &a, const VerifiedProgram &prog, const FrontTimes &ft,
               const std::vector<Lane> &lanes, const std::vector<Stats> &st,
               const std::vector<Ratio> &ratios, const std::vector<std::string> &notes) {
  std::ostringstream o;
  o << "program " << a.program << ": " << prog.stmts.size() << " statements, " << prog.slices.size()
    << " PLC2 slices; " << a.scans << " full scans per engine, inputs "
    << (a.stimulus.empty() ? "pseudo-random (seed " + std::to_string(a.seed) + ")"
                           : "from " + a.stimulus)
    << "\n\nfront end: read " << fmtUs(ft.readUs) << ", parse " << fmtUs(ft.parseUs) << ", verify "
    << fmtUs(ft.verifyUs) << "\n\ncompile (wall)\n";
  char line[256];
  std::snprintf(line, sizeof line, "  %-12s %10s %10s %10s %10s %10s %10s %10s %12s\n", "engine",
                "lower", "optimize", "codegen", "link", "cache", "load", "total", "code bytes");
  o << line;
  for (const Lane &l : lanes) {
    if (l.engine == "interp") continue;
    const Phases &p = l.phases;
    std::snprintf(line, sizeof line, "  %-12s %10s %10s %10s %10s %10s %10s %10s %12llu%s\n",
                  l.name.c_str(), fmtUs(p.lowerUs).c_str(), fmtUs(p.optimizeUs).c_str(),
                  fmtUs(p.codegenUs).c_str(), fmtUs(p.linkUs).c_str(), fmtUs(p.cacheUs).c_str(),
                  fmtUs(p.loadUs).c_str(), fmtUs(p.totalUs).c_str(),
                  static_cast<unsigned long long>(p.codeBytes), p.cacheHit ? " (cache hit)" : "");
    o << line;
  }
  o << "\nfull scan (PLC1 + every PLC2 slice)\n";
  std::snprintf(line, sizeof line, "  %-12s %12s %12s %12s %12s %8s\n", "engine", "min", "median",
                "p99", "ns/stmt", "faults");
  o << line;
  const double stmts =
      static_cast<double>((prog.plc1.end - prog.plc1.begin) + (prog.plc2.end - prog.plc2.begin));
  for (size_t i = 0; i < lanes.size(); ++i) {
    std::snprintf(line, sizeof line, "  %-12s %12s %12s %12s %12.3f %8llu\n", lanes[i].name.c_str(),
                  fmtNs(st[i].minNs).c_str(), fmtNs(st[i].medianNs).c_str(),
                  fmtNs(st[i].p99Ns).c_str(), stmts > 0 ? st[i].medianNs / stmts : 0.0,
                  static_cast<unsigned long long>(lanes[i].faults));
    o << line;
  }
  o << "\nratios of median scan times, A/B (same run; below 1 = A is faster)\n";
  for (const Ratio &r : ratios) {
    std::snprintf(line, sizeof line, "  %-22s %8.3f\n", r.name.c_str(), r.value);
    o << line;
  }
  o << "\nfinal states: every engine equals the interpreter after " << a.scans << " scans\n";
  for (const std::string &n : notes) o << "note: " << n << "\n";
  std::cout << o.str();
}

void printJson(const BenchArgs &a, double overheadNs, const VerifiedProgram &prog,
               const FrontTimes &ft, const std::vector<Lane> &lanes, const std::vector<Stats> &st,
               const std::vector<Ratio> &ratios, const std::vector<std::string> &notes) {
  nlohmann::json j;
  j["schema"] = "ladderjit-bench 1";
  j["program"] = a.program;
  j["statements"] = prog.stmts.size();
  j["scan_statements"] = (prog.plc1.end - prog.plc1.begin) + (prog.plc2.end - prog.plc2.begin);
  j["plc2_slices"] = prog.slices.size();
  j["scans"] = a.scans;
  j["inputs"] = a.stimulus.empty() ? "random" : "stimulus";
  j["seed"] = a.seed;
  j["clock_overhead_ns"] = overheadNs;
  j["front_end"] = {{"read_us", ft.readUs}, {"parse_us", ft.parseUs}, {"verify_us", ft.verifyUs}};
  j["engines"] = nlohmann::json::array();
  for (size_t i = 0; i < lanes.size(); ++i) {
    nlohmann::json e;
    e["name"] = lanes[i].name;
    e["engine"] = lanes[i].engine;
    e["tier"] = lanes[i].tier;
    if (lanes[i].engine != "interp") e["compile"] = phasesJson(lanes[i].phases);
    e["scan_ns"] = {{"min", st[i].minNs},
                    {"median", st[i].medianNs},
                    {"p99", st[i].p99Ns},
                    {"mean", st[i].meanNs}};
    e["faults"] = lanes[i].faults;
    e["state_matches_interp"] = true;
    j["engines"].push_back(e);
  }
  j["ratios"] = nlohmann::json::object();
  for (const Ratio &r : ratios) j["ratios"][r.name] = r.value;
  j["notes"] = notes;
  std::cout << j.dump(2) << "\n";
}

} // namespace lj::cli::bench
