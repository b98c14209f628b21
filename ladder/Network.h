// Rungs as networks (docs/ladder-json.md): a series/parallel tree per rung whose leaves are
// contacts, coils and function boxes, each keeping its statement id and source location. Built
// from a verified program (FromStl.cpp), turned back into statements (ToStl.cpp), written and
// read as JSON (Json.cpp) and shown as text (Text.cpp). Depends on the IR only.
#pragma once

#include "ir/Program.h"

#include <string>
#include <vector>

namespace lj::ladder {

/// One statement as a network shows it: the instruction, its operands as text (with the symbol
/// each was written as), its id, where it was written and the comments written with it.
struct Element {
  StmtId id = -1;
  SourceLoc loc;
  Op op = Op::LoadTrue;
  std::vector<std::string> operands; ///< address or constant text (`X1.0`, `D5`, `-3`)
  std::vector<std::string> symbols;  ///< parallel to operands: symbol name, or empty
  std::vector<std::string> before;   ///< comment lines just before it (not the rung comment)
  std::string comment;               ///< trailing comment on its line
  bool hasComment = false;
  /// The instruction as the user's dialect writes it (DialectText::spellStmt: FANUC `EQB`, IL
  /// `LD 1`); empty: the operation's neutral name. Drawings, the text form and the JSON use it.
  std::string drawn;
  bool drawnWhole = false; ///< `drawn` includes the operands (an IL label `%L64:`)
  /// Bit k: operand k is implied by the front end, not in the source (DialectText::implied);
  /// drawings leave it out, the JSON and text forms keep it (an IL label drawn whole excepted).
  uint32_t implied = 0;
  /// Its part in an instruction the front end recorded as written (ir/Program.h WrittenInstr):
  /// First holds the instruction's text in `written`, which networks -> program text prints for
  /// it and the Part statements after it (docs/ladder-json.md "written").
  WrittenRole role = WrittenRole::None;
  std::string written;
  /// In a rung's drawing (Rung::drawing): how the element shows its written instruction, and
  /// the ids of the other statements the front end made of it (drawn by this element).
  DrawAs form = DrawAs::Plain;
  std::vector<StmtId> covers;
  /// Set by toStatements on a rung's first statement: the rung's Rung::lead, which networks ->
  /// program text prints before it when it is printed from its statements.
  std::vector<std::string> lead;
};

enum class NodeKind : uint8_t { Series, Parallel, FanOut, Contact, Coil, Box };

/// How a contact behaves: normally open, normally closed, rising or falling edge, always true.
enum class ContactKind : uint8_t { NO, NC, Rise, Fall, True };

/// How a child after the first of a Series/Parallel was joined in the STL: Inline = AND/OR form
/// of a contact, Block = its own LD chain then ANB/ORB. Auto = whatever is canonical.
enum class Join : uint8_t { Auto, Inline, Block };

/// How a fan-out branch is entered: None = directly (outputs then continuation), Mps/Mrd/Mpp
/// = through the MS stack. Auto = canonical (direct when every earlier branch is outputs only).
enum class Entry : uint8_t { Auto, None, Mps, Mrd, Mpp };

/// A network node. Series/Parallel/FanOut have children (a FanOut's children are Series
/// branches from one junction); Contact, Coil and Box are leaves holding `elem`. A Box with
/// `inputs` takes one sub-network per ST entry it consumes; a Box without them takes the series
/// to its left (or the rail when `rail`).
struct Node {
  NodeKind kind = NodeKind::Series;
  Join join = Join::Auto;    ///< as a child of Series/Parallel
  Entry entry = Entry::Auto; ///< as a branch of a FanOut
  ContactKind contact = ContactKind::NO;
  bool rail = false;
  Element elem;
  /// The statement that joined this node (ANB/ORB for a Block child, MPS/MRD/MPP for a fan-out
  /// branch): its id, location and comments; `op` is implied by the place.
  Element link;
  std::vector<Node> children; ///< Series/Parallel/FanOut children; Box inputs
};

/// A rung: a drawable network, statements with no drawable form, or a marker.
struct Rung {
  enum class Kind : uint8_t { Ladder, Stl, Marker } kind = Kind::Ladder;
  std::vector<std::string> comment; ///< the comment block before the rung
  Node network;                     ///< Ladder: a Series
  std::vector<Element> stmts;       ///< Stl and Marker: the statements verbatim
  /// The rung as its user wrote it, for drawings only (layout, text form; docs/ladder-view.md
  /// "Dialects"), where the dialect draws a written instruction other than as the statements
  /// the front end made of it (DialectText::drawStmts): their elements merged into one with
  /// the written form, the statements the front end added on its own left out (`hidden`). Not
  /// set: drawn as the rung itself. The JSON and the statements never use it.
  struct Drawing {
    Kind kind = Kind::Ladder;
    Node network;
    std::vector<Element> stmts;
    std::vector<StmtId> hidden;
  };
  std::vector<Drawing> drawing; ///< none or one
  /// Lines written before the rung's first statement that made none of their own (FANUC
  /// `COME`, `NOP`; DialectText::markerLine), as written: drawn as markers before the rung, and
  /// printed before it when networks -> program text prints the rung from its statements (its
  /// first statement's `written` holds them too while that instruction is unchanged). The JSON's
  /// rung "lead" (docs/ladder-json.md).
  std::vector<std::string> lead;
};

/// A program part: "init", "PLC1", "PLC2" or a subroutine "S<n>".
struct Part {
  std::string name;
  std::vector<Rung> rungs;
};

/// A whole program as networks; the parts in order hold every statement once, in order.
struct Networks {
  std::string dialect = "hnc8";
  std::string file;
  std::vector<Part> parts;
  std::vector<Symbol> symbols;
  std::vector<std::string> trailingComments; ///< comment lines after the last statement
  /// The JSON's "source": the program text a non-HNC-8 JSON was made from (empty: none).
  std::string source;
  /// The dialect's words and text (the front end's DialectText); never null for networks made
  /// by fromProgram or readJson.
  const DialectText *text = nullptr;
  /// A grid source's drawing (ir/Program.h GridPartDrawing): drawings use it instead of the
  /// parts' networks; the networks stay the program (JSON, statements).
  std::vector<GridPartDrawing> grids;
};

/// The lines at the start of an instruction's written text (Element::written) that made no
/// statement and stand between rungs (DialectText::markerLine: FANUC `COME`): a rung's lead.
std::vector<std::string> leadLines(const DialectText *d, std::string_view written);

/// Networks of a verified program: every logic rung that has a network whose canonical STL
/// (with the recorded join/entry hints) is exactly its statements becomes Ladder, the others Stl.
Networks fromProgram(const VerifiedProgram &prog);

/// The statements of the networks in order (contacts get the LD/AND/OR form of their place;
/// a rung comment goes to its first statement's `before`). False with `error` naming the rung
/// and element when a network has no STL form. `where`, if given, gets one "PART rung R element
/// E" per statement.
bool toStatements(const Networks &nets, std::vector<Element> &out, std::string &error,
                  std::vector<std::string> *where = nullptr);

/// Statements of one ladder rung (see toStatements); false with `error` (element path, the
/// instructions named in `d`'s words).
bool rungStatements(const Node &network, std::vector<Element> &out, std::string &error,
                    const DialectText *d = nullptr);

/// `s` as the ladder view draws it in dialect `d` (docs/ladder-view.md "Dialects"): the front
/// end's DialectText::spellStmt, else its spelling of the operation.
std::string drawnMnemonic(const DialectText *d, const Stmt &s);
/// Statement `s` as an element of the networks, in dialect `d` (its word, its operands as the
/// dialect writes them, the symbols they were written as; `profile` names operands when `d` is
/// null): what fromProgram makes of every statement.
Element stmtElement(const Stmt &s, const DialectText *d, const TargetProfile *profile,
                    const std::vector<Symbol> &symbols);
/// An element's drawn instruction: `drawn`, else its operation's neutral name.
inline std::string drawnText(const Element &e) {
  return e.drawn.empty() ? instrInfo(e.op).name : e.drawn;
}

/// The words a drawing gives the joins of a network (not statements of any one dialect): the
/// block join of a sub-network and the push / read / pop of a fan-out's junction.
/// (ladder/Spelling.cpp, the one file of ladder/ that spells drawn words.)
extern const char *const kBlockJoinWord;
extern const char *const kFanWords[3];

/// Counts for reports: ladder / stl / marker rungs.
struct RungCounts {
  int64_t ladder = 0, stl = 0, marker = 0;
  /// fuzz --round-trip of FANUC / IEC: programs printed back in the dialect and read again
  /// (every program is: one that is not is a mismatch).
  int64_t printed = 0;
  /// Of their statements: how many, and how many an instruction recorded as written stands for
  /// (ir/Program.h WrittenInstr; the rest printed by the dialect's printer from the statement).
  int64_t statements = 0, asWritten = 0;
};
RungCounts countRungs(const Networks &nets);

} // namespace lj::ladder
