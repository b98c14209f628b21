// Helpers shared by the front-end tests: compile a snippet and keep its rendered diagnostics.
#pragma once

#include "frontends/hnc8/FrontEnd.h"
#include "pipeline/Compile.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::test {

/// Result of running the whole front end on one snippet.
struct Compiled {
  std::optional<VerifiedProgram> prog;
  std::string diags; ///< Diagnostics::render() output
  int errors = 0;
  int warnings = 0;
};

/// parseStl + verify on `text` as file "t.stl".
inline Compiled compile(std::string_view text, VerifyOptions opts = {}) {
  Compiled c;
  Diagnostics d("t.stl");
  c.prog = pipeline::compileStl(text, "t.stl", opts, d);
  c.diags = d.render();
  c.errors = d.errorCount();
  for (const Diagnostic &x : d.all())
    if (x.severity == Diagnostic::Severity::Warning) ++c.warnings;
  return c;
}

/// Only the parser: statements kept and rendered diagnostics.
struct Parsed {
  ParsedProgram prog;
  std::string diags;
  int errors = 0;
};

inline Parsed parse(std::string_view text) {
  Parsed p;
  Diagnostics d("t.stl");
  p.prog = parseStl(text, "t.stl", d);
  p.diags = d.render();
  p.errors = d.errorCount();
  return p;
}

} // namespace lj::test
