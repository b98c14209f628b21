// The ladder network JSON (docs/ladder-json.md): write, read back, and turn into STL text the
// HNC-8 parser reads, with a map from each generated line to its rung and element.
#pragma once

#include "ir/Diagnostics.h"
#include "ladder/Network.h"

#include <string>
#include <string_view>

namespace lj::ladder {

constexpr int kJsonVersion = 1;

/// The networks as JSON text (one object; schema docs/ladder-json.md). `source`, when not
/// empty, is written as the "source" member: the program text a JSON of a dialect other than
/// HNC-8 is read back through (docs/ladder-json.md "Other dialects").
std::string writeJson(const Networks &nets, std::string_view source = {});

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

/// Whether `given` (networks read from a JSON) hold the statements of `made` (the networks of
/// the program verified from the text the JSON carries): the same operations, operand texts,
/// symbols and statement ids in the same order; rung splits and comments may differ. False with
/// `error` naming the first difference by its place in `given`.
bool sameStatementsAs(const Networks &given, const Networks &made, std::string &error);

/// Diagnostics on generated STL, pointed back into the JSON (rung and element, recorded line).
std::string renderDiagnostics(const Diagnostics &diags, const StlFromJson &src);

/// Give the statements of a program verified from `src` their JSON ids and recorded lines.
void applyOrigins(VerifiedProgram &prog, const StlFromJson &src);

} // namespace lj::ladder
