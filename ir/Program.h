// The program model handed between stages (STYLE.md 5): source -> ParsedProgram ->
// VerifiedProgram. Checkers observe, lowerers transform; these types carry no behaviour.
#pragma once

#include "ir/Area.h"
#include "ir/OpTable.h"
#include "ir/SymbolTable.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lj {

struct TargetProfile;

/// A position in the source text (1-based line and column).
struct SourceLoc {
  int32_t line = 0;
  int32_t col = 0;
};

/// One operand as written: a constant, a register `D5`, a bit `X1.0`, a label `L3`, a
/// subroutine `S7`. Constants keep their value in `value`; registers their index.
struct Operand {
  enum class Kind : uint8_t { None, Const, Reg, Bit } kind = Kind::None;
  Area area = Area::None; ///< for Reg/Bit (L and S operands are Reg in area L / S)
  /// Reg: bytes read or written at the element's offset, little-endian (1, 2, 4; FANUC's
  /// byte-addressed areas): 0 = the area's element width. Bit: ignored.
  uint8_t width = 0;
  /// Reg: the bytes hold BCD digits (2 per byte); the instruction decides what an invalid digit
  /// does (front ends set it; engines honour it through the instruction's semantics).
  bool bcd = false;
  int32_t index = 0;   ///< element number (Reg/Bit)
  int8_t bit = -1;     ///< bit number (Bit)
  int16_t symbol = -1; ///< written as a symbol: index into the program's `symbols`
  int32_t value = 0;   ///< constant value (Const)
  SourceLoc loc;
};

/// Stable id of a statement within one program (its ordinal in source order for STL; carried
/// through the ladder JSON and back, docs/ladder-json.md).
using StmtId = int32_t;

/// One STL statement.
struct Stmt {
  Op op = Op::LoadTrue;
  uint8_t operandCount = 0;
  std::array<Operand, kMaxOperands> ops{};
  SourceLoc loc;
  StmtId id = -1;
};

/// A comment as written (`;` or `//` to the end of the line; text after the marker, trailing
/// blanks dropped). A comment on a line of its own belongs to the next statement (`stmt` is that
/// statement's index, or the statement count at the end); a trailing one to its line's statement.
struct Comment {
  int32_t line = 0;
  int32_t stmt = 0;
  bool trailing = false;
  std::string text;
};

/// A statement's part in an instruction the front end records as written (WrittenInstr).
enum class WrittenRole : uint8_t {
  None,  ///< printed from the statement itself
  First, ///< the first statement of a written instruction: printed as its written text
  Part,  ///< a later statement of one: printed by the first's text, nothing of its own
};

/// One instruction (or a run of source lines) as the user wrote it, where the dialect's printer
/// could not give the same statements back from the statements alone: an expansion the front end
/// made (FANUC CS/CM/CE, CALLU's (ON), IL N / XOR / END with their scratch bits, a BLK block),
/// or a FANUC functional instruction whose written parameters differ from its IR operands (DEC,
/// GTB, MOVE...). Statements [first, first + count) came from `text` (its lines, no comments;
/// several lines joined by '\n'; empty: the front end makes them on its own, such as IL block
/// presets). Networks carry it so that networks -> program text prints it back
/// (docs/ladder-json.md "Other dialects"). Not read by the engines.
struct WrittenInstr {
  int32_t first = 0;
  int32_t count = 0;
  std::string text;
  /// The source line `text` starts on where that is a line before its first statement's: a
  /// line that made no statement (FANUC COME) went with it. 0: its first statement's line.
  int32_t line = 0;
};

/// One statement of a network as text, for DialectText::printStmts: the operation (which fixes
/// the stack behaviour), the word it is written with (`instr`, empty: the dialect's spelling of
/// `op`), its operands as written (a symbol's name where one was used) and its comments.
struct StmtText {
  Op op = Op::LoadTrue;
  std::string instr;
  std::vector<std::string> operands;
  uint32_t implied = 0; ///< bit k: operand k is implied, not written (DialectText::implied)
  std::vector<std::string> before; ///< comment lines before it
  std::string comment;             ///< trailing comment
  bool hasComment = false;
  /// First: print `written` (WrittenInstr::text) instead of this statement and the Part ones
  /// after it; Part: printed by the First before it.
  WrittenRole role = WrittenRole::None;
  std::string written;
};

/// How a drawing shows an instruction as its user wrote it where the front end made it into
/// other statements (docs/ladder-view.md "Dialects"; DialectText::drawStmts).
enum class DrawAs : uint8_t {
  Plain,   ///< the statement's own element (no written form of its own)
  Hidden,  ///< a statement the front end added on its own (a label END jumps to): drawn by nothing
  Contact, ///< a contact-like element in a series, labelled as written (`XOR %M2`, `N`)
  Compare, ///< a comparison contact with its expression as written (`%MW0 > 5`)
  Operate, ///< an operation block with its expression as written (`%MW1 := %MW1 + 1`)
  Jump,    ///< a jump to a label (`JMPC %L1`)
  Call,    ///< a subroutine call (`SR0`)
  End,     ///< the end of the scan (`END`, `ENDC`)
  Return,  ///< the return of a subroutine (`RET`, `RETC`)
  Marker,  ///< a marker rung's word as written (FANUC `JMPE`, not the label it became)
};

/// One written instruction as the drawing shows it: the statements [i, i + count) it became, the
/// one whose id the drawn element carries, where it sits in the network and its text.
struct DrawnInstr {
  DrawAs as = DrawAs::Plain;
  int32_t count = 1; ///< statements from i the instruction became (>= 1)
  int32_t main = 0;  ///< offset from i of the statement whose id the element carries
  /// Its place in the network, as one statement of this operation would have it: Load starts a
  /// series, And / Or continue it in series / in parallel, Jump ends it (an output).
  Op op = Op::LoadTrue;
  bool fromRail = false; ///< an output without a condition (END, JMP, RET): drawn from the rail
  std::string text;      ///< as written, operands included (`XOR %M2`, `%MW0 > 5`, `ENDC`)
  std::string operand;   ///< its bit or label operand as written (`%M2`, `%L1`), or empty
};

/// How the core words an operation or an operand in a message: in the dialect the program was
/// written in. Set by the front end (frontends/hnc8/Mnemonics.cpp: hnc8::dialectText()).
struct DialectText {
  const char *name; ///< "hnc8"
  /// The mnemonic of an operation, or nullptr when the dialect does not spell it (ir/OpTable.h
  /// "dialect-only rows"); callers go through spelling(), which never returns null.
  const char *(*spell)(Op);
  std::string (*formatOperand)(const Operand &); ///< an operand as source text
  /// Whether operand `k` of `op` is implied by the front end, not written in this dialect's
  /// source (a fixed time unit the dialect's instruction has no parameter for): drawings leave
  /// it out. nullptr: every operand is written.
  bool (*implied)(Op op, int k) = nullptr;
  /// The instruction of statement `s` as this dialect's user writes it, where the operation
  /// alone does not say (FANUC `MOVW` for a two-byte Move, `EQB`, IL `LD 1`): what drawings and
  /// the network JSON name it by (docs/ladder-json.md). nullptr: spelling(this, s.op).
  std::string (*spellStmt)(const Stmt &s) = nullptr;
  /// The operation a word of this dialect names (what spell() or spellStmt() gave: `RD`,
  /// `EQB`, `LD`), false when it names none. How the network JSON's "instr" is read back.
  bool (*lookup)(std::string_view word, Op &op) = nullptr;
  /// Statements as program text of this dialect (networks -> text, the inverse of the front
  /// end; docs/ladder-json.md "Other dialects"), appended to `out` line by line with their
  /// comments in the dialect's syntax. False with `error` ("statement K: ...") for one that has
  /// no text form. nullptr: the dialect prints no text.
  bool (*printStmts)(std::span<const StmtText> stmts, std::string &out,
                     std::string &error) = nullptr;
  /// What this dialect's symbol table accepts (ir/SymbolTable.h): how a ladder JSON's symbols
  /// are read back. nullptr: the dialect has no symbol table.
  const SymbolRules &(*symbolRules)() = nullptr;
  /// The instruction written at statement `i` of `stmts` (a part of a program, in order) where
  /// the drawing shows it other than as the statements' own elements: the statements the front
  /// end made of one written instruction (IL `XOR`, `END`, `RET`, `[%MW0 > 5]`) or added on its
  /// own. False: statement `i` is drawn as itself. nullptr: every statement is.
  bool (*drawStmts)(std::span<const Stmt> stmts, size_t i, DrawnInstr &out) = nullptr;
  /// A comment as the dialect writes it, for drawings: opening and closing (IL `(*`, `*)`).
  /// nullptr: `;` to the end of the line (HNC-8, FANUC).
  const char *commentOpen = nullptr;
  const char *commentClose = nullptr;
  /// An instruction the front end recorded as written (WrittenInstr::text, one line) as the
  /// dialect's drawings name it, where its written word is a code rather than a name (FANUC
  /// `SUB 25 0001 D0 100 R10` drawn as `DECB 0001 D0 100 R10`). nullptr: drawn as written.
  std::string (*drawWritten)(std::string_view written) = nullptr;
  /// Whether a line of an instruction recorded as written is one that made no statement and
  /// stands between rungs (FANUC `COME`, `NOP`): drawings show it as a marker before the rung
  /// whose statement carries it. nullptr: none is.
  bool (*markerLine)(std::string_view line) = nullptr;
};

/// Whether dialect `d` spells `op`.
inline bool spells(const DialectText &d, Op op) { return d.spell(op) != nullptr; }

/// The mnemonic of `op` in `d`, or its neutral name (InstrInfo::name) without a dialect or
/// when `d` has no spelling for it.
inline const char *spelling(const DialectText *d, Op op) {
  const char *s = d ? d->spell(op) : nullptr;
  return s ? s : instrInfo(op).name;
}

/// A line the parser dropped although its mnemonic was known (bad operands or count). The
/// verifier applies its stack effect, silently, so one bad operand causes no follow-on errors.
struct DroppedStmt {
  int32_t before = 0; ///< index in ParsedProgram::stmts of the next kept statement
  Op op = Op::LoadTrue;
};

/// A program whose source is a grid of cells (a ClassicLadder rung: each element in its cell,
/// vertical wires between rows): how its editor draws it, for drawings only (docs/ladder-view.md
/// "Grid sources"). The statements are the program; this says where each drawn element sits.
struct GridCellDrawing {
  int32_t row = 0, col = 0, width = 1, height = 1;
  /// A ladder Layout cell kind: contact-no|nc|rise|fall, coil, coil-not, set, rst, box, compare,
  /// operate, jump, call, wire, vlink (a vertical wire on the boundary left of `col`, from the
  /// middle of `row` down `height` rows).
  std::string kind;
  std::string text;                  ///< the variable or block as the editor shows it (`%I0`)
  std::string symbol;                ///< the variable's symbol, or empty
  std::vector<std::string> operands; ///< a block's parameters, as shown
  std::vector<int32_t> pins;         ///< a block's input rows, from `row`
  StmtId stmt = -1; ///< the statement whose traced value the live view shows, or -1
};
struct GridRungDrawing {
  std::vector<std::string> comment; ///< the rung's label and comment
  int32_t rows = 0, cols = 0;
  std::vector<GridCellDrawing> cells;
};
struct GridPartDrawing {
  std::string name; ///< the section, as the editor names it
  std::vector<GridRungDrawing> rungs;
};

/// What the parser produces: statements in source order (markers included).
struct ParsedProgram {
  std::string file;                       ///< name used in diagnostics
  const DialectText *dialect = nullptr;   ///< the front end that read it
  const TargetProfile *profile = nullptr; ///< the target it was written for (set by the front end)
  std::vector<Stmt> stmts;
  std::vector<DroppedStmt> dropped;   ///< in source order (`before` non-decreasing)
  std::vector<Comment> comments;      ///< in source order
  std::vector<Symbol> symbols;        ///< the symbol table the program was parsed with
  std::vector<WrittenInstr> written;  ///< by `first`, disjoint (WrittenInstr)
  std::vector<GridPartDrawing> grids; ///< a grid source's drawing (GridRungDrawing), or empty
};

/// A half-open range of statement indices [begin, end).
struct StmtRange {
  int32_t begin = 0;
  int32_t end = 0;
  bool empty() const { return begin >= end; }
};

/// A rung: a run of statements with no ST entry live across its start and MS empty there
/// (verify/Rungs.cpp). Markers (IEND, 1END, 2END, SP, SPE, LBL, LOOP, NEXT) are rungs of
/// their own. The ladder stage (ladder/) gives each logic rung its network.
struct RungRange {
  enum class Kind : uint8_t { Logic, Marker } kind = Kind::Logic;
  StmtRange range;
};

/// Facts the verifier computes for one statement.
struct StmtInfo {
  int32_t depth = 0;     ///< ST depth before the statement (statically known)
  int32_t msDepth = 0;   ///< MS depth before the statement
  int32_t target = -1;   ///< JMP: index of its LBL; LOOP: index of its NEXT; NEXT: its LOOP;
                         ///< CALL: index into VerifiedProgram::subs; JumpOut: index of its
                         ///< LBL in the sliced part
  int32_t slot = -1;     ///< edge slot (LDP..ORF, CTR, EVENT, SAVEDATA), timer/counter slot
                         ///< (lj_tc_slot), PLS/PLF/ALT number, or first inst_word (Words)
  bool hasInput = false; ///< a block reads ST0 (false: ST empty, input is 1)
  bool backward = false; ///< JMP whose label comes before it (counts a watchdog step)
};

/// A subroutine `SP Sn ... SPE`: body = statements strictly between SP and SPE.
struct Subroutine {
  int32_t number = 0;
  int32_t spIndex = 0;
  StmtRange body;
};

/// A verified program: every fact the engines need, computed once by the front end.
struct VerifiedProgram {
  std::string file;
  const DialectText *dialect = nullptr;   ///< copied from ParsedProgram
  const TargetProfile *profile = nullptr; ///< copied from ParsedProgram (never null once verified)
  std::vector<Stmt> stmts;
  std::vector<StmtInfo> info; ///< parallel to stmts
  StmtRange init;             ///< statements of the init part (markers excluded)
  StmtRange plc1;
  StmtRange plc2;
  std::vector<Subroutine> subs;
  /// S number -> index into subs, -1 if undefined; max(512, the profile's Subroutine count)
  /// entries (FANUC P1..P5000).
  std::vector<int16_t> subByNumber;
  /// PLC2 slices, in order; at least one (possibly empty). Their union is `plc2`.
  std::vector<StmtRange> slices;
  /// ST depth at the start of each slice (entries left by the previous slice are dead).
  std::vector<int32_t> sliceDepth;
  int32_t edgeSlots = 0; ///< edge slots used (<= LJ_EDGE_SLOTS)
  /// EdgePolicy::PerObject (ir/Profile.h): the object whose previous-scan image edge slot k
  /// holds (kind None: a slot of its own instruction, not an object's). The engines copy each
  /// object's bit into its slot at the end of every run of the cyclic part; edge contacts only
  /// compare with it. Empty under EdgePolicy::PerInstance.
  std::vector<Operand> edgeObjects;
  int32_t wordSlots = 0;    ///< inst_word entries used (<= LJ_INST_WORDS)
  int32_t plc2Nvalue = 200; ///< the slicing parameter these slices were planned with
  int32_t maxDepth = 0;     ///< deepest ST anywhere (for interpreter stack sizing)
  int32_t maxMsDepth = 0;
  std::vector<Comment> comments;      ///< as parsed
  std::vector<Symbol> symbols;        ///< as parsed (Operand::symbol indexes it)
  std::vector<WrittenInstr> written;  ///< as parsed
  std::vector<GridPartDrawing> grids; ///< as parsed
  /// Every statement in exactly one rung, in order (Rungs.cpp). A slice boundary is always a
  /// rung boundary.
  std::vector<RungRange> rungs;
  /// Where a CALL of the sliced part goes on when its callee (or a subroutine that callee
  /// calls) takes a JumpOut (FANUC JMPC): (CALL index, LBL index) pairs sorted by CALL index,
  /// one per label the call can reach. The slice planner and the chunker keep each pair in one
  /// piece, like a JMP and its LBL.
  std::vector<std::pair<int32_t, int32_t>> callExits;
};

/// The (CALL, LBL) pairs of `p.callExits` for the CALL at statement `call` (none: empty).
inline std::span<const std::pair<int32_t, int32_t>> exitsOfCall(const VerifiedProgram &p,
                                                                int32_t call) {
  auto lo = std::lower_bound(p.callExits.begin(), p.callExits.end(), std::make_pair(call, -1));
  auto hi = lo;
  while (hi != p.callExits.end() && hi->first == call) ++hi;
  return {lo, hi};
}

} // namespace lj
