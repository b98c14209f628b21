// The round-trip engine of `ladderjit fuzz --round-trip`: the program turned into networks, JSON
// text, networks again, program text of its dialect (HNC-8 STL, FANUC mnemonics, IEC IL: every
// rung printed), verified anew and run on the interpreter, as the engine under test against the
// interpreter on the original (program -> networks -> program). The networks of the new program
// must hold the statements of the networks it was printed from, and the same instructions
// recorded as written (networks -> program -> networks). No fallback: a program that cannot be
// printed is an error.
#include "fuzz/RoundTrip.h"

#include "ladder/Json.h"
#include "pipeline/Compile.h"

namespace lj::fuzz {

namespace {

/// An interpreter that owns the program it runs (the round-tripped twin).
class OwningEngine : public Engine {
public:
  OwningEngine(std::unique_ptr<VerifiedProgram> prog) : prog_(std::move(prog)) {
    inner_ = makeInterpreterEngine(*prog_);
  }
  const lj_entries &entries() const override { return inner_->entries(); }
  const char *name() const override { return "roundtrip"; }

private:
  std::unique_ptr<VerifiedProgram> prog_;
  std::unique_ptr<Engine> inner_;
};

/// Whether `a` and `b` record the same instructions as written (ladder::Element::role and
/// written) on the same statements.
bool sameWritten(const ladder::Networks &a, const ladder::Networks &b, std::string &error) {
  std::vector<ladder::Element> x, y;
  std::vector<std::string> where;
  if (!ladder::toStatements(a, x, error, &where) || !ladder::toStatements(b, y, error))
    return false;
  for (size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i].role != y[i].role || x[i].written != y[i].written) {
      error = where[i] + ": written as '" + x[i].written + "', read back as '" + y[i].written +
              "' (roles " + std::to_string(static_cast<int>(x[i].role)) + ", " +
              std::to_string(static_cast<int>(y[i].role)) + ")";
      return false;
    }
  return true;
}

} // namespace

EngineFactory roundTripFactory(std::shared_ptr<ladder::RungCounts> counts) {
  return [counts](const VerifiedProgram &prog, bool,
                  std::string &error) -> std::unique_ptr<Engine> {
    ladder::Networks nets = ladder::fromProgram(prog);
    if (counts) {
      ladder::RungCounts c = ladder::countRungs(nets);
      counts->ladder += c.ladder;
      counts->stl += c.stl;
      counts->marker += c.marker;
    }
    std::string json = ladder::writeJson(nets);
    const std::string dialect = prog.dialect ? prog.dialect->name : "hnc8";
    if (dialect != "hnc8") {
      // A FANUC / IEC JSON: networks -> JSON -> networks hold exactly this program's
      // statements; then every rung printed in the dialect (ladder::programText; an instruction
      // the front end recorded as written printed as written) and read by the dialect's front
      // end is the twin (docs/ladder-json.md "Other dialects"). A program that cannot be printed,
      // or whose text does not verify or reads back as other statements, is an error.
      ladder::Networks back;
      if (!ladder::readJson(json, back, error, *prog.dialect) ||
          !ladder::sameStatementsAs(back, nets, error)) {
        error = "round trip: " + error;
        return nullptr;
      }
      std::string text;
      if (!ladder::programText(back, prog, "", text, error, true)) {
        error = "round trip: networks -> program text: " + error;
        return nullptr;
      }
      if (dialect == "fanuc") text += "END\n"; // the source's last line, not a statement
      Diagnostics diags("roundtrip");
      VerifyOptions vo;
      vo.plc2Nvalue = prog.plc2Nvalue;
      std::optional<VerifiedProgram> twin =
          dialect == "fanuc" ? pipeline::compilePmc(text, "roundtrip.pmc", vo, diags, nullptr)
                             : pipeline::compileIl(text, "roundtrip.il", vo, diags);
      if (!twin || diags.hasErrors()) {
        error = "round trip: the printed program text does not verify:\n" + diags.render() +
                "--- printed program text ---\n" + text;
        return nullptr;
      }
      // networks -> program -> networks: the twin's networks hold the statements they were
      // printed from, with the same instructions recorded as written.
      const ladder::Networks again = ladder::fromProgram(*twin);
      if (!ladder::sameStatementsAs(back, again, error, false) ||
          !sameWritten(back, again, error)) {
        error = "round trip: the printed program text reads back as other statements: " + error +
                "\n--- printed program text ---\n" + text;
        return nullptr;
      }
      if (counts) {
        ++counts->printed;
        counts->statements += static_cast<int64_t>(prog.stmts.size());
        for (const WrittenInstr &w : prog.written) counts->asWritten += w.count;
      }
      return std::make_unique<OwningEngine>(std::make_unique<VerifiedProgram>(std::move(*twin)));
    }
    ladder::StlFromJson src;
    if (!ladder::stlFromJson(json, src, error, *prog.dialect)) {
      error = "round trip: " + error;
      return nullptr;
    }
    Diagnostics diags("roundtrip.json");
    VerifyOptions vo;
    vo.plc2Nvalue = prog.plc2Nvalue;
    std::optional<VerifiedProgram> twin =
        pipeline::compileStl(src.text, "roundtrip.json", vo, diags, &src.symbols);
    if (!twin) {
      error = "round trip: the regenerated STL does not verify:\n" +
              ladder::renderDiagnostics(diags, src) + "--- regenerated STL ---\n" + src.text;
      return nullptr;
    }
    ladder::applyOrigins(*twin, src);
    return std::make_unique<OwningEngine>(std::make_unique<VerifiedProgram>(std::move(*twin)));
  };
}

} // namespace lj::fuzz
