// libFuzzer target for the front end: any bytes -> parseStl + verify (+ printProgram and the
// ladder networks, their text and their JSON read back, when the program is accepted). The front
// end and the ladder stage must never crash, hang or read out of bounds.
#include "frontends/hnc8/FrontEnd.h"
#include "ladder/Json.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"
#include "tests/fuzz/ProgramInvariants.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text(reinterpret_cast<const char *>(data), size);
  lj::Diagnostics diags("fuzz.stl");
  lj::VerifyOptions opts;
  // Small slices so the slice planner runs on every accepted PLC2.
  opts.plc2Nvalue = size % 7;
  std::optional<lj::VerifiedProgram> prog = lj::pipeline::compileStl(text, "fuzz.stl", opts, diags);
  if (prog) {
    lj::fuzztest::checkProgramInvariants(*prog);
    (void)lj::printProgram(*prog);
    // Its ladder networks: the text form, and the JSON read back as PROGRAM must verify again
    // with the same statements (what `ladderjit ladder --format json` promises).
    lj::ladder::Networks nets = lj::ladder::fromProgram(*prog);
    (void)lj::ladder::renderText(nets);
    lj::ladder::StlFromJson back;
    std::string error;
    if (!lj::ladder::stlFromJson(lj::ladder::writeJson(nets), back, error, *prog->dialect))
      __builtin_trap();
    lj::Diagnostics again("fuzz.json");
    std::optional<lj::VerifiedProgram> twin =
        lj::pipeline::compileStl(back.text, "fuzz.json", opts, again, &back.symbols);
    if (!twin || twin->stmts.size() != prog->stmts.size()) __builtin_trap();
  }
  (void)diags.render();
  return 0;
}
