// libFuzzer target for the FANUC PMC and IEC IL front ends (built twice: LJ_FUZZ_FANUC for
// fuzz_pmc, else fuzz_il): any bytes -> compilePmc / compileIl, and for an accepted program its
// ladder networks, their text form and their JSON read back (what `ladderjit ladder` does with
// it). Neither front end nor the ladder stage may crash, hang or read out of bounds on any input.
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/iec/FrontEnd.h"
#include "ladder/Json.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"
#include "tests/fuzz/ProgramInvariants.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text(reinterpret_cast<const char *>(data), size);
#ifdef LJ_FUZZ_FANUC
  const char *file = "fuzz.pmc";
#else
  const char *file = "fuzz.il";
#endif
  lj::Diagnostics diags(file);
  lj::VerifyOptions opts;
  opts.plc2Nvalue = size % 7; // small slices: the slice planner runs on every accepted level 2
#ifdef LJ_FUZZ_FANUC
  std::optional<lj::VerifiedProgram> prog =
      lj::pipeline::compilePmc(text, file, opts, diags, nullptr);
#else
  std::optional<lj::VerifiedProgram> prog = lj::pipeline::compileIl(text, file, opts, diags);
#endif
  if (prog) {
    lj::fuzztest::checkProgramInvariants(*prog);
    lj::ladder::Networks nets = lj::ladder::fromProgram(*prog);
    (void)lj::ladder::renderText(nets);
    // The JSON written is read back, and holds exactly the program's statements.
    lj::ladder::Networks back;
    std::string error;
    if (!lj::ladder::readJson(lj::ladder::writeJson(nets, text), back, error, *prog->dialect) ||
        !lj::ladder::sameStatementsAs(back, nets, error))
      __builtin_trap();
  }
  (void)diags.render();
  return 0;
}
