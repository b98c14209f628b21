// `ladderjit bench --corpus` (docs/bench.md "Shape corpus"): every shape of gen/ShapeCorpus.h
// generated, then measured like `bench PROGRAM --tier opt --c-baseline` in rounds (lanes
// started in turn each round), and the per-shape ratio of jit-opt and aot to the best C
// compiler setting of the same sitting. Every lane's final state is checked against the
// interpreter's, as in every bench run.
#include "tools/ladderjit/BenchCmd.h"
#include "tools/ladderjit/Commands.h"

#include "gen/CTranslate.h"
#include "gen/ShapeCorpus.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace lj::cli::bench {

namespace {

double medianOf(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

/// One lane's result in one shape.
struct LaneResult {
  std::string name, engine;
  double medianNs = 0; ///< median of the round medians
  std::vector<double> roundsNs;
  double compileUs = 0;
};

struct ShapeResult {
  std::string name;
  int32_t statements = 0;
  std::vector<LaneResult> lanes;
  std::string bestC;
  double bestCNs = 0;
  double jitRatio = 0, aotRatio = 0; ///< median over best C median (0: lane missing)
};

const LaneResult *laneNamed(const ShapeResult &r, const std::string &n) {
  for (const LaneResult &l : r.lanes)
    if (l.name == n) return &l;
  return nullptr;
}

std::string fmt(const char *f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

void printTable(const std::vector<ShapeResult> &res) {
  std::vector<std::string> cols;
  for (const ShapeResult &r : res)
    for (const LaneResult &l : r.lanes)
      if (l.name != "interp" && std::find(cols.begin(), cols.end(), l.name) == cols.end())
        cols.push_back(l.name);
  std::cout << "\n| shape | stmts |";
  for (const std::string &c : cols) std::cout << " " << c << " |";
  std::cout << " best C | jit-opt / best C | aot / best C |\n|---|---:|";
  for (size_t i = 0; i < cols.size(); ++i) std::cout << "---:|";
  std::cout << "---|---:|---:|\n";
  for (const ShapeResult &r : res) {
    std::cout << "| " << r.name << " | " << r.statements << " |";
    for (const std::string &c : cols) {
      const LaneResult *l = laneNamed(r, c);
      std::cout << " " << (l ? fmt("%.0f", l->medianNs) : "-") << " |";
    }
    std::cout << " " << (r.bestC.empty() ? "-" : r.bestC) << " | "
              << (r.jitRatio > 0 ? fmt("%.3f", r.jitRatio) : "-") << " | "
              << (r.aotRatio > 0 ? fmt("%.3f", r.aotRatio) : "-") << " |\n";
  }
  std::cout << "\nscan medians in ns (median of the round medians); compile, wall ms:\n\n| shape |";
  for (const std::string &c : cols) std::cout << " " << c << " |";
  std::cout << "\n|---|";
  for (size_t i = 0; i < cols.size(); ++i) std::cout << "---:|";
  std::cout << "\n";
  for (const ShapeResult &r : res) {
    std::cout << "| " << r.name << " |";
    for (const std::string &c : cols) {
      const LaneResult *l = laneNamed(r, c);
      std::cout << " " << (l ? fmt("%.0f", l->compileUs / 1000) : "-") << " |";
    }
    std::cout << "\n";
  }
}

void printJsonResult(const BenchArgs &a, const std::vector<ShapeResult> &res) {
  std::ostringstream o;
  o << "{\n  \"schema\": \"ladderjit-bench-corpus 1\",\n  \"statements\": " << a.statements
    << ",\n  \"scans\": " << a.scans << ",\n  \"rounds\": " << a.rounds
    << ",\n  \"seed\": " << a.seed << ",\n  \"shapes\": [";
  for (size_t i = 0; i < res.size(); ++i) {
    const ShapeResult &r = res[i];
    o << (i ? "," : "") << "\n    { \"name\": \"" << r.name
      << "\", \"statements\": " << r.statements << ", \"best_c\": \"" << r.bestC
      << "\", \"ratios\": { \"jit-opt/best-c\": " << fmt("%.4f", r.jitRatio)
      << ", \"aot/best-c\": " << fmt("%.4f", r.aotRatio) << " },\n      \"engines\": {";
    for (size_t k = 0; k < r.lanes.size(); ++k) {
      const LaneResult &l = r.lanes[k];
      o << (k ? "," : "") << "\n        \"" << l.name
        << "\": { \"median_ns\": " << fmt("%.1f", l.medianNs)
        << ", \"compile_us\": " << fmt("%.0f", l.compileUs) << ", \"rounds_ns\": [";
      for (size_t j = 0; j < l.roundsNs.size(); ++j)
        o << (j ? ", " : "") << fmt("%.1f", l.roundsNs[j]);
      o << "] }";
    }
    o << "\n      } }";
  }
  o << "\n  ]\n}\n";
  std::cout << o.str();
}

} // namespace

int runCorpus(const BenchArgs &a) {
  if (!a.program.empty()) return usageError("bench --corpus takes no PROGRAM");
  if (a.rounds < 1 || a.rounds > 1000) return usageError("--rounds: expected 1..1000");
  if (a.statements < 40 || a.statements > 1000000)
    return usageError("--statements: expected 40..1000000");
  if (a.format != "text" && a.format != "json")
    return usageError("--format: expected text or json, got '" + a.format + "'");
  std::vector<std::string> wanted;
  {
    std::stringstream ss(a.shapes);
    std::string n;
    while (std::getline(ss, n, ','))
      if (!n.empty()) wanted.push_back(n);
  }
  const std::vector<gen::CorpusShape> &shapes = gen::corpusShapes();
  for (const std::string &w : wanted)
    if (std::none_of(shapes.begin(), shapes.end(),
                     [&](const gen::CorpusShape &s) { return s.name == w; }))
      return usageError("--shapes: no shape '" + w + "'");

  std::string dir = a.keepPrograms;
  bool temp = dir.empty();
  if (temp) {
    const char *tmp = std::getenv("TMPDIR");
    std::string t = std::string(tmp && *tmp ? tmp : "/tmp") + "/ladderjit-corpus-XXXXXX";
    if (!::mkdtemp(t.data()))
      return usageError("cannot create a temporary directory: " +
                        std::string(std::strerror(errno)));
    dir = t;
  }
  struct Cleanup {
    std::string path;
    ~Cleanup() {
      std::error_code ec;
      if (!path.empty()) std::filesystem::remove_all(path, ec);
    }
  } cleanup{temp ? dir : std::string()};

  std::vector<ShapeResult> results;
  for (size_t i = 0; i < shapes.size(); ++i) {
    const gen::CorpusShape &shape = shapes[i];
    if (!wanted.empty() && std::find(wanted.begin(), wanted.end(), shape.name) == wanted.end())
      continue;
    const std::string path = dir + "/" + shape.name + shape.extension;
    {
      std::ofstream out(path, std::ios::trunc);
      out << gen::generateShape(shape.name, 20330000u + i, a.statements).text() << '\n';
      if (!out) return usageError("cannot write " + path);
    }
    BenchArgs b = a;
    b.corpus = false;
    b.program = path;
    b.engine = "all";
    b.tier = "opt";
    b.cBaseline = true;
    b.dialect.clear();
    std::fprintf(stderr, "bench --corpus: %s ...\n", shape.name.c_str());
    Measured m;
    if (int code = measure(b, m, a.rounds); code != kOk) {
      std::fprintf(stderr, "ladderjit: error: bench --corpus: shape %s failed\n",
                   shape.name.c_str());
      return code;
    }
    for (const std::string &n : m.notes)
      if (n.rfind("scan times:", 0) != 0) std::fprintf(stderr, "  note: %s\n", n.c_str());
    if (!temp) { // --keep-programs: the C baseline's translation beside the program
      std::ofstream c(dir + "/" + shape.name + ".c", std::ios::trunc);
      c << gen::translateToC(*m.prog);
    }
    ShapeResult r;
    r.name = shape.name;
    r.statements = static_cast<int32_t>(m.prog->stmts.size());
    for (size_t k = 0; k < m.lanes.size(); ++k) {
      LaneResult l;
      l.name = m.lanes[k].name;
      l.engine = m.lanes[k].engine;
      l.roundsNs = m.roundMedians[k];
      l.medianNs = medianOf(l.roundsNs);
      l.compileUs = m.lanes[k].phases.totalUs;
      if (l.engine == "c" && (r.bestC.empty() || l.medianNs < r.bestCNs)) {
        r.bestC = l.name;
        r.bestCNs = l.medianNs;
      }
      r.lanes.push_back(std::move(l));
    }
    if (r.bestCNs > 0) {
      if (const LaneResult *j = laneNamed(r, "jit-opt")) r.jitRatio = j->medianNs / r.bestCNs;
      if (const LaneResult *o = laneNamed(r, "aot")) r.aotRatio = o->medianNs / r.bestCNs;
    }
    std::fprintf(stderr, "  %s: jit-opt / %s %.3f, aot / %s %.3f\n", r.name.c_str(),
                 r.bestC.c_str(), r.jitRatio, r.bestC.c_str(), r.aotRatio);
    results.push_back(std::move(r));
  }
  if (a.format == "json")
    printJsonResult(a, results);
  else
    printTable(results);
  return kOk;
}

} // namespace lj::cli::bench
