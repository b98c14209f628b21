// The FANUC diagnostics tests' one helper: the rendered located diagnostics of a `.pmc` text.
#pragma once

#include "frontends/fanuc/FrontEnd.h"
#include "pipeline/Compile.h"

#include <optional>
#include <string>

namespace lj::test {

/// Every diagnostic of compiling `text` as `t.pmc`, rendered (empty when it compiles cleanly).
inline std::string fanucDiags(const std::string &text) {
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(text, "t.pmc", VerifyOptions{}, d, nullptr);
  return d.render();
}

} // namespace lj::test
