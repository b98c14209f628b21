// bench_online_change: how long a one-rung online change of a program takes to give new code,
// with the incremental compile (JitOptions::incremental) in one JIT session as `serve` uses it.
//   bench_online_change PROGRAM [--changes N] [--threads T] [--full] [--quick]
// Compiles PROGRAM once (cold), then N times: edits one rung (the operand of one contact
// statement, a different rung each time, spread over the program), writes nothing to disk,
// parses + verifies the edited text and compiles it as a new version; prints per change the
// front-end and compile phases (wall, and the CPU time of the front end and of the compile over
// its threads, which a loaded machine inflates less), the leaves compiled / reused, then
// min / median / max. --quick compiles the changed groups at the fast tier (what serve's online
// change does, JitOptions::quickLeaves) and then, as serve's background optimizer does, the
// same program again without it ("opt" column: that rebuild's wall time). --full compiles
// every version without the incremental compile, for comparison.
#include "jit/Jit.h"
#include "pipeline/ProgramFile.h"

#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

namespace {

double msSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// Lines "LD Xa.b" / "AND Xa.b" / "OR Xa.b" ... (a contact on X with a bit): the edit sites.
std::vector<size_t> contactLines(const std::vector<std::string> &lines) {
  std::vector<size_t> out;
  for (size_t i = 0; i < lines.size(); ++i) {
    const std::string &l = lines[i];
    size_t sp = l.find(' ');
    if (sp == std::string::npos || l.size() < sp + 4) continue;
    std::string op = l.substr(0, sp);
    if (op != "LD" && op != "LDI" && op != "AND" && op != "ANI" && op != "OR" && op != "ORI")
      continue;
    if (l[sp + 1] == 'X' && l.find('.', sp) != std::string::npos) out.push_back(i);
  }
  return out;
}

/// The same contact on the next bit of its byte (X7.3 -> X7.4, X7.7 -> X7.0).
std::string nextBit(const std::string &line) {
  std::string l = line;
  size_t dot = l.find('.');
  char &b = l[dot + 1];
  b = b == '7' ? '0' : static_cast<char>(b + 1);
  return l;
}

double cpuMs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) / 1e6;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

} // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: bench_online_change PROGRAM [--changes N] [--threads T] [--full] "
                         "[--quick]\n");
    return 2;
  }
  int changes = 20, threads = 0;
  bool full = false, quick = false;
  for (int i = 2; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--changes") && i + 1 < argc)
      changes = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
      threads = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--full"))
      full = true;
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else {
      std::fprintf(stderr, "bench_online_change: unknown option '%s'\n", argv[i]);
      return 2;
    }
  }
  lj::pipeline::ProgramSource src;
  if (lj::Status st = lj::pipeline::readProgramFile(argv[1], src); !st.ok()) {
    std::fprintf(stderr, "bench_online_change: %s\n", st.message().c_str());
    return 2;
  }
  std::vector<std::string> lines;
  {
    std::istringstream in(src.text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
  }
  const std::vector<size_t> sites = contactLines(lines);
  if (sites.empty()) {
    std::fprintf(stderr, "bench_online_change: no X contact to edit in %s\n", argv[1]);
    return 2;
  }
  std::string error;
  std::shared_ptr<lj::jit::Session> session =
      lj::jit::Session::create(lj::jit::Tier::Optimizing, error);
  if (!session) {
    std::fprintf(stderr, "bench_online_change: %s\n", error.c_str());
    return 2;
  }
  if (!full) session->enableIncremental();
  lj::jit::JitOptions jo;
  jo.compileThreads = threads;
  // Versions stay alive as in serve until the next one replaced them.
  std::unique_ptr<lj::VerifiedProgram> prog, prevProg;
  std::unique_ptr<lj::Engine> engine, prevEngine;
  std::vector<double> totals, compiles, cpus, feCpus, opts;
  std::printf("program %s: %zu lines, %zu edit sites, %s compile%s, %d threads (0 = all)\n",
              argv[1], lines.size(), sites.size(), full ? "whole-program" : "incremental",
              quick ? " (changed groups at the fast tier, then optimized)" : "", threads);
  std::printf("%-6s %8s %7s %7s %7s %7s %7s %7s %8s %8s %7s %7s %8s\n", "change", "frontend",
              "fe-cpu", "keys", "lower", "spine", "leaves", "link", "compile", "total", "cpu",
              "new", "opt");
  for (int c = 0; c <= changes; ++c) {
    if (c > 0) {
      size_t site =
          sites[(static_cast<size_t>(c) * 7919u * sites.size() / 20011u + c) % sites.size()];
      lines[site] = nextBit(lines[site]);
      src.text.clear();
      for (const std::string &l : lines) src.text += l + "\n";
    }
    auto t0 = std::chrono::steady_clock::now();
    const double fc0 = cpuMs();
    std::string diags;
    std::optional<lj::VerifiedProgram> v = lj::pipeline::verifyProgram(src, 200, diags);
    if (!v) {
      std::fprintf(stderr, "bench_online_change: %s\n", diags.c_str());
      return 1;
    }
    auto p = std::make_unique<lj::VerifiedProgram>(std::move(*v));
    const double fe = msSince(t0), feCpu = cpuMs() - fc0;
    auto t1 = std::chrono::steady_clock::now();
    lj::jit::CompileTimes t;
    jo.quickLeaves = quick && c > 0;
    std::unique_ptr<lj::Engine> e = session->compile(*p, jo, error, &t);
    if (!e) {
      std::fprintf(stderr, "bench_online_change: %s\n", error.c_str());
      return 1;
    }
    const double comp = msSince(t1), total = msSince(t0);
    double opt = 0;
    if (jo.quickLeaves && t.leavesQuick > 0) {
      // serve's background optimizer: the same program, the changed groups optimized.
      auto t2 = std::chrono::steady_clock::now();
      jo.quickLeaves = false;
      std::unique_ptr<lj::Engine> o = session->compile(*p, jo, error);
      if (!o) {
        std::fprintf(stderr, "bench_online_change: optimizing: %s\n", error.c_str());
        return 1;
      }
      opt = msSince(t2);
      e = std::move(o);
    }
    char spine[16];
    std::snprintf(spine, sizeof spine, "%s", t.spineCached ? "cached" : "");
    if (!t.spineCached) std::snprintf(spine, sizeof spine, "%.2f", t.spineUs / 1000);
    std::printf("%-6s %8.2f %7.2f %7.2f %7.2f %7s %7.2f %7.2f %8.2f %8.2f %7.2f %3u/%-3u %8.2f\n",
                c == 0 ? "cold" : std::to_string(c).c_str(), fe, feCpu, t.keysUs / 1000,
                t.lowerUs / 1000, spine, (t.codegenUs - t.linkUs - t.cacheUs - t.spineUs) / 1000,
                t.linkUs / 1000, comp, total, t.cpuUs / 1000, t.leavesCompiled, t.leaves, opt);
    if (c > 0) {
      totals.push_back(total);
      compiles.push_back(comp);
      cpus.push_back(t.cpuUs / 1000);
      feCpus.push_back(feCpu);
      if (opt > 0) opts.push_back(opt);
    }
    prevEngine = std::move(engine);
    prevProg = std::move(prog);
    engine = std::move(e);
    prog = std::move(p);
  }
  if (!totals.empty())
    std::printf("one-rung change, %zu changes: request -> new code ready (parse + verify + "
                "compile + link) min %.2f / median %.2f / max %.2f ms; compile alone median "
                "%.2f ms (compile CPU median %.2f ms: lower + optimize + codegen + link, all "
                "threads; front-end CPU median %.2f ms)\n",
                totals.size(), *std::min_element(totals.begin(), totals.end()), median(totals),
                *std::max_element(totals.begin(), totals.end()), median(compiles), median(cpus),
                median(feCpus));
  if (!opts.empty())
    std::printf("background optimized rebuild of the changed groups: median %.2f ms\n",
                median(opts));
  return 0;
}
