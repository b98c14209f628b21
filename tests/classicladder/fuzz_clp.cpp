// libFuzzer target: the ClassicLadder reader (.clp and .clprj containers) and the evaluation of
// every expression of what it accepts. Built with -DLADDERJIT_FUZZERS=ON and clang.
#include "frontends/classicladder/Reader.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  std::string text(reinterpret_cast<const char *>(data), size);
  bool upstream = size > 0 && (data[0] & 1);
  auto r = lj::classicladder::readProjectText(text, upstream ? "f.clprj" : "f.clp");
  if (!r.ok()) return 0;
  auto read = [](const lj::classicladder::VarRef &v) { return v.type + v.num; };
  for (const auto &[i, a] : r->expressions) {
    (void)i;
    if (a.expr.isCompare) (void)lj::classicladder::evaluateCompare(a.expr, read);
    if (a.expr.isOperate) (void)lj::classicladder::evaluate(*a.expr.value, read);
  }
  return 0;
}
