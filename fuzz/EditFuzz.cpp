// `ladderjit fuzz --edit` (EditFuzz.h): the editor's grid against its oracle.
#include "fuzz/EditFuzz.h"

#include "formats/Address.h"
#include "gen/GridGen.h"
#include "hosts/TestHost.h"
#include "ir/Engine.h"
#include "ladder/GridEval.h"
#include "pipeline/Dialects.h"

#include <chrono>
#include <iomanip>
#include <memory>
#include <ostream>
#include <set>

namespace lj::fuzz {

namespace {

using ladder::GridPart;

constexpr const char *kReasons[9] = {"element after an output",
                                     "unconnected",
                                     "short circuit",
                                     "no series/parallel form",
                                     "two networks in a rung",
                                     "no output",
                                     "address",
                                     "no text in the dialect",
                                     "other"};

int reasonOf(const std::string &m) {
  if (m.find("after an output") != std::string::npos) return 0;
  if (m.find("unconnected") != std::string::npos) return 1;
  if (m.find("short circuit") != std::string::npos) return 2;
  if (m.find("parted before") != std::string::npos) return 3;
  if (m.find("second network") != std::string::npos) return 4;
  if (m.find("no output") != std::string::npos) return 5;
  if (m.find("address") != std::string::npos || m.find("'") == 0) return 6;
  if (m.find("has no text for it") != std::string::npos) return 7;
  return 8;
}

/// What one check of a grid program found.
struct Check {
  enum class Kind : uint8_t { Same, Refused, Mismatch, RoundTrip, NotVerified } kind = Kind::Same;
  std::string detail;
  std::string text; ///< the program text
  std::vector<ladder::GridError> errors;
  uint32_t ticks = 0;
};

class Checker {
public:
  explicit Checker(const pipeline::Dialect &d) : d_(d), text_(d.text()) {
    pools_ = gen::gridPools(d.name);
    const std::string_view name = d.name;
    if (name == "fanuc") partEnd_ = {"END1\nEND2\nEND"};
    check_ = [this](ladder::CellKind, const std::string &operand, std::string &error) {
      std::optional<formats::CliAddress> a = d_.parseAddress(operand, error);
      if (!a) return false;
      if (!a->isBit()) {
        error = "not a bit address";
        return false;
      }
      return true;
    };
    for (const std::string &a : pools_.inputs) addresses_.push_back(address(a));
    for (const std::string &a : pools_.outputs) addresses_.push_back(address(a));
  }

  const gen::GridPools &pools() const { return pools_; }

  /// Program text, or the located errors of a grid the dialect cannot express.
  bool program(const std::vector<GridPart> &parts, std::string &text,
               std::vector<ladder::GridError> &errors) const {
    text.clear();
    return ladder::gridProgramText(parts, text_, check_, partEnd_, text, errors);
  }

  /// `exact`: the round trip must give the grid back as it is (a grid the view placed);
  /// otherwise the grid read back must print the same program text.
  Check run(const std::vector<GridPart> &parts, uint64_t seed, uint32_t ticks, bool exact) const {
    Check c;
    if (!program(parts, c.text, c.errors)) {
      c.kind = Check::Kind::Refused;
      c.detail = c.errors.empty() ? "refused" : c.errors[0].text();
      return c;
    }
    Diagnostics diags("edit");
    std::optional<VerifiedProgram> prog =
        d_.compile(c.text, std::string("edit.") + d_.name, VerifyOptions{}, diags, nullptr);
    if (!prog || diags.hasErrors()) {
      c.kind = Check::Kind::NotVerified;
      c.detail = "the program of a valid grid does not verify:\n" + diags.render();
      return c;
    }
    // Evaluator against the interpreter, tick for tick.
    ladder::GridEvaluator eval;
    std::string error;
    if (!eval.load(parts, error)) {
      c.kind = Check::Kind::Mismatch;
      c.detail = error;
      return c;
    }
    std::unique_ptr<Engine> interp = makeInterpreterEngine(*prog);
    auto state = std::make_unique<lj_state>();
    lj_state_reset(state.get());
    hosts::TestHost host(0);
    host.attach(*state);
    ladder::BitImage bits;
    gen::Rng rng(seed);
    uint32_t f = lj_run_init(state.get(), &interp->entries());
    if (f != LJ_FAULT_NONE) {
      c.kind = Check::Kind::Mismatch;
      c.detail = "init faulted: " + std::to_string(f);
      return c;
    }
    const size_t inputs = pools_.inputs.size();
    for (uint32_t t = 0; t < ticks; ++t) {
      std::string stim;
      for (size_t i = 0; i < inputs; ++i) {
        const bool v = rng.chance(t % 7 == 3 ? 10 : 50);
        bits[pools_.inputs[i]] = v;
        formats::writeAddress(*state, addresses_[i], v ? 1 : 0);
        if (v) stim += " " + pools_.inputs[i];
      }
      state->now_ms = static_cast<uint64_t>(t) * 10;
      f = lj_tick(state.get(), &interp->entries());
      eval.scan(bits);
      ++c.ticks;
      if (f != LJ_FAULT_NONE) {
        c.kind = Check::Kind::Mismatch;
        c.detail =
            "tick " + std::to_string(t) + ": the interpreter faulted (" + std::to_string(f) + ")";
        return c;
      }
      for (size_t i = 0; i < addresses_.size(); ++i) {
        const std::string &name = i < inputs ? pools_.inputs[i] : pools_.outputs[i - inputs];
        const bool want = bits.count(name) && bits[name];
        const bool got = formats::readAddress(*state, addresses_[i]) != 0;
        if (want != got) {
          c.kind = Check::Kind::Mismatch;
          c.detail = "tick " + std::to_string(t) + ": " + name +
                     " grid evaluator=" + std::to_string(want) +
                     " interpreter=" + std::to_string(got) +
                     " (inputs on:" + (stim.empty() ? " none" : stim) + ")";
          return c;
        }
      }
    }
    // grid -> program -> networks -> grid.
    ladder::Networks nets = ladder::fromProgram(*prog);
    std::vector<GridPart> back(1);
    back[0].name = parts.empty() ? "PLC1" : parts[0].name;
    for (const ladder::Part &p : nets.parts)
      for (size_t r = 0; r < p.rungs.size(); ++r) {
        const ladder::Rung &rung = p.rungs[r];
        if (rung.kind == ladder::Rung::Kind::Marker) continue;
        ladder::GridRung g;
        if (!ladder::gridOfRung(rung, g, error)) {
          c.kind = Check::Kind::RoundTrip;
          c.detail = "round trip: " + p.name + " rung " + std::to_string(r + 1) + ": " + error;
          return c;
        }
        back[0].rungs.push_back(std::move(g));
      }
    const size_t want = parts.empty() ? 0 : parts[0].rungs.size();
    if (back[0].rungs.size() != want) {
      c.kind = Check::Kind::RoundTrip;
      c.detail = "round trip: " + std::to_string(want) + " rungs became " +
                 std::to_string(back[0].rungs.size());
      return c;
    }
    for (size_t r = 0; r < want; ++r) {
      if (exact && !(back[0].rungs[r] == parts[0].rungs[r])) {
        c.kind = Check::Kind::RoundTrip;
        c.detail = "round trip: rung " + std::to_string(r + 1) + " came back as\n" +
                   ladder::gridText(back[0].rungs[r]);
        return c;
      }
    }
    if (!exact) {
      std::string again;
      std::vector<ladder::GridError> errs;
      if (!program(back, again, errs) || again != c.text) {
        c.kind = Check::Kind::RoundTrip;
        c.detail = "round trip: the grid read back prints\n" +
                   (errs.empty() ? again : errs[0].text()) + "\ninstead of the program";
        return c;
      }
    }
    return c;
  }

private:
  formats::CliAddress address(const std::string &a) const {
    std::string error;
    return d_.parseAddress(a, error).value_or(formats::CliAddress{});
  }

  const pipeline::Dialect &d_;
  const DialectText &text_;
  gen::GridPools pools_;
  std::vector<std::string> partEnd_;
  ladder::OperandCheck check_;
  std::vector<formats::CliAddress> addresses_;
};

std::string draw(const std::vector<GridPart> &parts) {
  std::string s;
  for (const GridPart &p : parts)
    for (size_t r = 0; r < p.rungs.size(); ++r)
      s += p.name + " rung " + std::to_string(r + 1) + ":\n" + ladder::gridText(p.rungs[r]);
  return s;
}

/// Shrink a failing grid program: drop rungs, then turn cells into lines or nothing, while the
/// check still fails the same way.
std::vector<GridPart> minimize(const Checker &ck, std::vector<GridPart> parts, uint64_t seed,
                               uint32_t ticks, bool exact, Check::Kind kind, uint32_t budget) {
  auto fails = [&](const std::vector<GridPart> &p) {
    if (budget == 0) return false;
    --budget;
    return ck.run(p, seed, ticks, exact).kind == kind;
  };
  for (size_t r = parts[0].rungs.size(); r-- > 0 && parts[0].rungs.size() > 1;) {
    std::vector<GridPart> t = parts;
    t[0].rungs.erase(t[0].rungs.begin() + static_cast<long>(r));
    if (fails(t)) parts = std::move(t);
  }
  for (size_t r = 0; r < parts[0].rungs.size(); ++r)
    for (size_t i = 0; i < parts[0].rungs[r].cells.size(); ++i) {
      ladder::CellKind k = parts[0].rungs[r].cells[i].kind;
      if (!ladder::isContactCell(k)) continue;
      std::vector<GridPart> t = parts;
      t[0].rungs[r].cells[i] = ladder::GridCell{ladder::CellKind::Wire, {}, {}, {}};
      if (fails(t)) parts = std::move(t);
    }
  return parts;
}

} // namespace

const char *editFuzzReason(int k) { return k >= 0 && k < 9 ? kReasons[k] : "?"; }

EditFuzzStats runEdit(const EditFuzzOptions &opts, std::ostream &out) {
  EditFuzzStats st;
  const auto start = std::chrono::steady_clock::now();
  const pipeline::Dialect *d = pipeline::dialectNamed(opts.dialect);
  if (!d || gen::gridPools(opts.dialect).inputs.empty()) {
    out << "fuzz --edit: no grids for dialect '" << opts.dialect << "'\n";
    ++st.notVerified;
    return st;
  }
  Checker ck(*d);
  gen::Rng master(opts.seed);
  uint32_t reports = 0;
  auto report = [&](const char *what, const std::vector<GridPart> &parts, uint64_t seed, bool exact,
                    const Check &c, const std::string &history) {
    if (reports++ >= opts.maxReports) return;
    std::vector<GridPart> small =
        minimize(ck, parts, seed, opts.ticks, exact, c.kind, opts.minimizeBudget);
    Check again = ck.run(small, seed, opts.ticks, exact);
    if (again.kind != c.kind) {
      small = parts;
      again = c;
    }
    out << "=== " << what << " (program seed " << seed << ")" << history << "\n"
        << again.detail << "\n--- minimized grid ---\n"
        << draw(small) << "--- its program ---\n"
        << again.text << "---\n";
  };
  auto count = [&](const Check &c, const char *what, const std::vector<GridPart> &parts,
                   uint64_t seed, bool exact, const std::string &history) {
    st.ticks += c.ticks;
    switch (c.kind) {
    case Check::Kind::Same:
    case Check::Kind::Refused:
      return;
    case Check::Kind::Mismatch:
      ++st.mismatches;
      break;
    case Check::Kind::RoundTrip:
      ++st.roundTrip;
      break;
    case Check::Kind::NotVerified:
      ++st.notVerified;
      break;
    }
    report(what, parts, seed, exact, c, history);
  };
  for (uint64_t n = 0; n < opts.programs; ++n) {
    const uint64_t seed = master.fork();
    gen::Rng rng(seed);
    std::vector<GridPart> parts = gen::randomGrids(rng, ck.pools(), opts.maxRungs);
    ++st.programs;
    st.rungs += parts[0].rungs.size();
    // The generated grid: as the view placed it, so the round trip gives it back exactly.
    Check c = ck.run(parts, seed, opts.ticks, true);
    ++st.checked;
    if (c.kind == Check::Kind::Refused) { // a generated grid is valid: count it as a failure
      c.kind = Check::Kind::NotVerified;
      c.detail = "a generated grid was refused: " + c.detail;
    }
    count(c, "generated grid", parts, seed, true, "");
    // An edit sequence: an edit that leaves the grid invalid is refused and undone, as the
    // editor marks the cell and 更新修改 refuses the draft.
    const int edits = static_cast<int>(rng.range(1, std::max(1, opts.maxEdits)));
    std::string history;
    bool kept = false;
    for (int k = 0; k < edits; ++k) {
      gen::GridEdit e = gen::randomEdit(rng, parts, ck.pools());
      std::vector<GridPart> next = parts;
      gen::applyEdit(next, e);
      ++st.edits;
      std::string text;
      std::vector<ladder::GridError> errors;
      if (!ck.program(next, text, errors)) {
        ++st.refused;
        if (!errors.empty()) {
          const ladder::GridError &x = errors[0];
          const ladder::GridRung &g = next[0].rungs[static_cast<size_t>(std::max(0, x.rung - 1))];
          if (x.rung < 1 || x.row < 0 || x.col < 0 || x.row >= g.rows || x.col >= g.cols) {
            ++st.unlocated;
            out << "=== unlocated refusal: " << x.text() << "\n" << draw(next);
          }
          ++st.refusedBy[reasonOf(x.message)];
        }
        continue;
      }
      ++st.editsKept;
      kept = true;
      history += "\n  edit: " + e.text();
      parts = std::move(next);
    }
    if (kept) {
      Check ce = ck.run(parts, seed ^ 0x5EEDull, opts.ticks, false);
      ++st.checked;
      count(ce, "edited grid", parts, seed ^ 0x5EEDull, false, history);
    }
    if (opts.progress)
      opts.progress(
          n + 1, st.failures(),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  out << "fuzz --edit: dialect " << opts.dialect << ", seed " << opts.seed << ", " << st.programs
      << " grid programs (" << st.rungs << " rungs), " << opts.ticks << " ticks each\n"
      << "edits: " << st.edits << " tried, " << st.editsKept << " kept, " << st.refused
      << " refused with a located error (";
  bool first = true;
  for (int k = 0; k < 9; ++k)
    if (st.refusedBy[k]) {
      out << (first ? "" : ", ") << kReasons[k] << " " << st.refusedBy[k];
      first = false;
    }
  out << ")\n"
      << "checked: " << st.checked << " grids against the interpreter, " << st.ticks << " ticks\n"
      << "mismatches: " << st.failures() << " (evaluator " << st.mismatches << ", round trip "
      << st.roundTrip << ", not verified " << st.notVerified << ", unlocated " << st.unlocated
      << ")\n"
      << "time: " << std::fixed << std::setprecision(1) << st.seconds << " s\n";
  return st;
}

} // namespace lj::fuzz
