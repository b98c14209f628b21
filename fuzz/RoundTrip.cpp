// The round-trip engine of `ladderjit fuzz --round-trip`: the program turned into networks, JSON
// text, networks again, STL, verified anew and run on the interpreter, as the engine under test
// against the interpreter on the original. FANUC and IEC programs: networks -> JSON -> networks
// must give back exactly the program's statements (their JSON is read through its program text).
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
    if (prog.dialect && std::string(prog.dialect->name) != "hnc8") {
      // A FANUC / IEC JSON is read back through the program text it carries, verified by the
      // dialect's front end as this program was: what must hold is that the networks read
      // from the JSON are exactly this program's statements (docs/ladder-json.md "Other
      // dialects"). The twin is then this program itself.
      ladder::Networks back;
      if (!ladder::readJson(json, back, error) || !ladder::sameStatementsAs(back, nets, error)) {
        error = "round trip: " + error;
        return nullptr;
      }
      return std::make_unique<OwningEngine>(std::make_unique<VerifiedProgram>(prog));
    }
    ladder::StlFromJson src;
    if (!ladder::stlFromJson(json, src, error)) {
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
