// The ladder network JSON (docs/ladder-json.md): write, read back, and turn into program text
// of its dialect: STL for the HNC-8 parser, with a map from each generated line to its rung and
// element; FANUC mnemonics and IEC IL through the dialect's DialectText (programText).
#pragma once

#include "ir/Diagnostics.h"
#include "ladder/Network.h"

#include <string>
#include <string_view>

namespace lj::ladder {

constexpr int kJsonVersion = 1;

/// The networks as JSON text (one object; schema docs/ladder-json.md), the instructions named in
/// the words of the networks' dialect. `source`, when not empty, is written as the "source"
/// member: the program text a JSON of a dialect other than HNC-8 keeps its untouched rungs from
/// (docs/ladder-json.md "Other dialects").
std::string writeJson(const Networks &nets, std::string_view source = {});

/// Parse the JSON form of dialect `d` (the words of its "instr" members: DialectText::lookup,
/// or an operation's neutral name). False with `error` naming the place
/// (`parts[1].rungs[3].network...`), also when the JSON names another dialect.
bool readJson(std::string_view text, Networks &out, std::string &error, const DialectText &d);

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
                    std::vector<LineOrigin> *origins, const DialectText *d);

/// JSON PROGRAM of HNC-8 (`d`) -> STL. False with `error` for bad JSON or a network with no STL
/// form.
bool stlFromJson(std::string_view json, StlFromJson &out, std::string &error, const DialectText &d);

/// An element as the dialect printer takes it (DialectText::printStmts): its operation, its
/// drawn instruction, operands as written (the symbol where one was written), comments.
StmtText stmtTextOf(const Element &e);

/// Networks -> program text in their dialect (docs/ladder-json.md "Other dialects"): the inverse
/// of the front end. `src` is the program verified from `srcText` (the JSON's "source"); each
/// run of rungs whose statements the networks hold unchanged (operations, operands, symbols,
/// ids and comments) is copied from `srcText` byte for byte, the rest is printed by the
/// dialect (DialectText::printStmts), so the result is `srcText` itself when nothing was
/// edited. `printAll`: print every rung (what `fuzz --round-trip` checks the printer with).
/// False with `error` naming the rung and element of a statement with no text form.
/// `origins`, when given, receives one LineOrigin per line of `out` (where = the place in
/// `given` of the statement on it, or of the next one for a comment line; a printed rung's lines
/// are given its statements in order, exact where the dialect prints one statement a line).
bool programText(const Networks &given, const VerifiedProgram &src, std::string_view srcText,
                 std::string &out, std::string &error, bool printAll = false,
                 std::vector<LineOrigin> *origins = nullptr);

/// Whether `given` (networks read from a JSON) hold the statements of `made` (the networks of
/// the program verified from the text the JSON carries): the same operations, operand texts,
/// symbols and statement ids (unless `compareIds` is false) in the same order; rung splits and
/// comments may differ. False with `error` naming the first difference by its place in `given`.
bool sameStatementsAs(const Networks &given, const Networks &made, std::string &error,
                      bool compareIds = true);

/// Diagnostics on generated STL, pointed back into the JSON (rung and element, recorded line).
std::string renderDiagnostics(const Diagnostics &diags, const StlFromJson &src);

/// Give the statements of a program verified from `src` their JSON ids and recorded lines.
void applyOrigins(VerifiedProgram &prog, const StlFromJson &src);

} // namespace lj::ladder
