// The round-trip engine of `ladderjit fuzz --round-trip`: the program turned into networks, JSON
// text, networks again, program text of its dialect (HNC-8 STL, FANUC mnemonics, IEC IL: every
// rung printed), verified anew and run on the interpreter, as the engine under test against the
// interpreter on the original (program -> networks -> program). The networks of the new program
// must hold the statements of the networks it was printed from (networks -> program -> networks).
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
      // statements; then every rung printed in the dialect (ladder::programText) and read by
      // the dialect's front end is the twin (docs/ladder-json.md "Other dialects").
      ladder::Networks back;
      if (!ladder::readJson(json, back, error, *prog.dialect) ||
          !ladder::sameStatementsAs(back, nets, error)) {
        error = "round trip: " + error;
        return nullptr;
      }
      std::string text;
      if (!ladder::programText(back, prog, "", text, error, true)) {
        // A statement the front end made on its own (no text form): the networks -> JSON ->
        // networks check above is what holds; the twin is the program itself.
        if (error.find("no FANUC mnemonic form") == std::string::npos &&
            error.find("has no IL form") == std::string::npos) {
          error = "round trip: " + error;
          return nullptr;
        }
        if (counts) ++counts->unprinted;
        error.clear();
        return std::make_unique<OwningEngine>(std::make_unique<VerifiedProgram>(prog));
      }
      if (dialect == "fanuc") text += "END\n"; // the source's last line, not a statement
      Diagnostics diags("roundtrip");
      VerifyOptions vo;
      vo.plc2Nvalue = prog.plc2Nvalue;
      std::optional<VerifiedProgram> twin =
          dialect == "fanuc" ? pipeline::compilePmc(text, "roundtrip.pmc", vo, diags, nullptr)
                             : pipeline::compileIl(text, "roundtrip.il", vo, diags);
      // Known gaps of the printers (docs/ladder-json.md "Other dialects"): a FANUC functional
      // instruction whose written parameters differ from its IR operands, an IL expansion's
      // scratch bits. The front end refuses such text, or it reads back as other statements
      // (refused for an edited JSON too), so it never runs; counted, the twin is the program.
      if (!twin || diags.hasErrors() ||
          !ladder::sameStatementsAs(back, ladder::fromProgram(*twin), error, false)) {
        if (counts) ++counts->unprinted;
        error.clear();
        return std::make_unique<OwningEngine>(std::make_unique<VerifiedProgram>(prog));
      }
      if (counts) ++counts->printed;
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
