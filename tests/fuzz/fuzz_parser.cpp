// libFuzzer target for the front end: any bytes -> parseStl + verify (+ printProgram when the
// program is accepted). The front end must never crash, hang or read out of bounds.
#include "frontends/hnc8/FrontEnd.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string_view text(reinterpret_cast<const char *>(data), size);
  lj::Diagnostics diags("fuzz.stl");
  lj::VerifyOptions opts;
  // Small slices so the slice planner runs on every accepted PLC2.
  opts.plc2Nvalue = size % 7;
  std::optional<lj::VerifiedProgram> prog = lj::compileFrontEnd(text, "fuzz.stl", opts, diags);
  if (prog) {
    // Invariants every engine relies on (Program.h); a violation is a front-end bug.
    if (prog->info.size() != prog->stmts.size() || prog->slices.empty() ||
        prog->slices.size() != prog->sliceDepth.size() ||
        prog->slices.front().begin != prog->plc2.begin || prog->slices.back().end != prog->plc2.end)
      __builtin_trap();
    for (size_t k = 1; k < prog->slices.size(); ++k)
      if (prog->slices[k].begin != prog->slices[k - 1].end) __builtin_trap();
    (void)lj::printProgram(*prog);
  }
  (void)diags.render();
  return 0;
}
