// The ladder network JSON (docs/ladder-json.md): write, read back, and turn into STL text the
// HNC-8 parser reads, with a map from each generated line to its rung and element.
#pragma once

#include "ir/Diagnostics.h"
#include "ladder/Network.h"

#include <string>
#include <string_view>

namespace lj::ladder {

constexpr int kJsonVersion = 1;

/// The networks as JSON text (one object; schema docs/ladder-json.md).
std::string writeJson(const Networks &nets);

/// Parse the JSON form. False with `error` naming the place (`parts[1].rungs[3].network...`).
bool readJson(std::string_view text, Networks &out, std::string &error);

/// Where one line of generated STL came from.
struct LineOrigin {
  std::string where; ///< "PLC1 rung 3 element 2", empty for comment lines
  SourceLoc loc;     ///< the element's recorded source location (0:0 if none)
  StmtId id = -1;
};

/// STL text for the HNC-8 parser, made from a JSON PROGRAM.
struct StlFromJson {
  std::string text;
  SymbolTable symbols;
  std::vector<LineOrigin> lines; ///< index = generated line - 1
};

/// STL text of statements (symbols written as the names they were written as) and, when
/// `origins` is given, one LineOrigin per line.
std::string stlText(const std::vector<Element> &stmts, const std::vector<std::string> *where,
                    std::vector<LineOrigin> *origins);

/// JSON PROGRAM -> STL. False with `error` for bad JSON or a network with no STL form.
bool stlFromJson(std::string_view json, StlFromJson &out, std::string &error);

/// Diagnostics on generated STL, pointed back into the JSON (rung and element, recorded line).
std::string renderDiagnostics(const Diagnostics &diags, const StlFromJson &src);

/// Give the statements of a program verified from `src` their JSON ids and recorded lines.
void applyOrigins(VerifiedProgram &prog, const StlFromJson &src);

} // namespace lj::ladder
