// Internals of the FANUC front end shared by Parser.cpp (lines, basic instructions, operands)
// and Functional.cpp (the functional instructions: SUB numbers, names, parameters).
#pragma once

#include "ir/Bcd.h"
#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "ir/SymbolTable.h"

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace lj::fanuc::detail {

struct Token {
  std::string_view text;
  SourceLoc loc;
};

/// The open COM..COME and JMP..JMPE regions of the program being parsed (DataFunctional.cpp).
struct FlowRegions {
  int32_t comStmt = -1; ///< index of the open COM's statement, -1: none open
  int32_t comLine = 0;
  int32_t jmpLabel = -1; ///< the hidden label of the open JMP, -1: none open
  int32_t jmpLine = 0;
  bool jmpInsideCom = false; ///< the open JMP was opened after the open COM
  int32_t nextLabel = 10000; ///< hidden JMPE labels: above the user's L1..L9999
  // fanuc-e: the open CS..CE select-call list (SelectCall in Functional.cpp).
  int32_t csLine = 0;  ///< line of the open CS, 0: none open
  int32_t csCount = 0; ///< CM lines so far in the open list
  Operand csIndex;     ///< the open CS's index address (2-byte binary)
  bool csOk = false;   ///< the open CS was emitted (else its CM/CE lines emit nothing)
};

/// What one functional instruction needs from the parser: its tokens and a way to check and
/// emit statements.
class Emitter {
public:
  virtual ~Emitter() = default;
  /// A located error with its stable code (docs/diagnostics.md, LJ4001..).
  virtual void error(SourceLoc at, const char *code, std::string msg) = 0;
  /// A bit address (`R0.0`); `writes`: must be writable.
  virtual bool bitOperand(const Token &t, bool writes, Operand &out) = 0;
  /// A byte address read/written as `width` bytes (`D100`), or with `constOk` a decimal
  /// constant; `writes`: must be writable.
  virtual bool dataOperand(const Token &t, int width, bool constOk, bool writes, Operand &out) = 0;
  /// A decimal constant in [lo, hi].
  virtual bool constant(const Token &t, int64_t lo, int64_t hi, const char *role, int64_t &v) = 0;
  /// A label `L1` or a subroutine `P1`.
  virtual bool labelOperand(const Token &t, Area a, Operand &out) = 0;
  virtual void emit(Op op, SourceLoc loc, std::initializer_list<Operand> ops) = 0;
  /// ST0..ST7 entries in use (ACT is ST0).
  virtual int depth() const = 0;
  virtual void setDepth(int d) = 0;
  /// 1, 2 or 3 while in level 1, 2, 3; 4 in the subroutine part.
  virtual int level() const = 0;
  /// An edge / timer number used by this program: false (and an error) when used before.
  virtual bool claimNumber(char space, int64_t n, SourceLoc at) = 0;
  /// Statements emitted so far (the index the next one gets).
  virtual int32_t stmtCount() const = 0;
  /// The open COM / JMP regions (fanuc-b instructions, DataFunctional.cpp).
  virtual FlowRegions &regions() = 0;
};

/// A functional instruction written `SUB n` or by name, with its parameters (the rest of its
/// line and the `(PRM)` lines after it).
struct Functional {
  Token head;   ///< `SUB` or the name
  Token number; ///< the SUB number token (empty text when written by name)
  std::vector<Token> params;
};

/// Whether `name` (upper case) is a functional instruction this front end knows by name.
bool isFunctionalName(std::string_view name);

/// Check and emit one functional instruction.
void emitFunctional(Emitter &e, const Functional &f);

/// TimerCounter.cpp: TMR, TMRC, CTR, CTRB, CTRC, COMPB, COMP, COIN, NEx, RNGx (SUB `sub`,
/// named `what` in messages); false when `sub` is none of them.
bool emitTimerCounter(Emitter &e, const Functional &f, int sub, const std::string &what);
// ---- fanuc-b: transfer, search, conversion and flow instructions (DataFunctional.cpp) ----
/// Check and emit `name` (XMOVB, DSCHB, PARI, SFT, COD, CODB, DCNV, DCNVB, DEC, DECB, COM, COME,
/// JMP, JMPE, NOP, XMOV, DSCH, ROT, ROTB; DISPB .. PSGN2 as "not supported"); false for a name it
/// does not handle.
bool emitDataFunctional(Emitter &e, const Functional &f, std::string_view name,
                        const std::string &what);
/// A WRT / WRT.NOT / SET / RST (`op`) of `bit` inside an open COM: emitted gated (true).
bool emitCommonCoil(Emitter &e, Op op, const Operand &bit, SourceLoc at);
/// At a level or subroutine boundary `marker` (END1, SP...): an open COM or JMP is an error.
void closeRegions(Emitter &e, std::string_view marker, SourceLoc at);
/// The FANUC mnemonic of the fanuc-b operations, nullptr for any other.
const char *spellData(Op op);

// ---- fanuc-c: arithmetic and constants (ArithFunctional.cpp) ----
/// Check and emit SUB `sub` when it is ADDB, SUBB, MULB, DIVB, ADD, SUB, MUL, DIV, NUMEB or NUME
/// (named `what` in messages); false for any other.
bool emitArithFunctional(Emitter &e, const Functional &f, int sub, const std::string &what);
/// The FANUC mnemonic of the fanuc-c operations, nullptr for any other.
const char *spellArith(Op op);
/// fanuc-e: at a level or subroutine boundary `marker`, an open CS..CE list is an error.
void closeSelect(Emitter &e, std::string_view marker, SourceLoc at);
/// fanuc-e: `head` (upper case; `sub` its SUB number or -1) at `at` while a CS list is open
/// and it is not a CM or CE line: an error (true).
bool insideSelect(Emitter &e, std::string_view head, int64_t sub, SourceLoc at);

/// The name of the functional instruction `SUB sub` (reference 6.1), nullptr for none.
const char *functionalName(int64_t sub);

// ---- networks as mnemonic text (NetworkText.cpp) ----
/// The instruction of `s` as a FANUC user writes it (DialectText::spellStmt).
std::string spellStatement(const Stmt &s);
/// The operation a mnemonic names (DialectText::lookup).
bool lookupWord(std::string_view w, Op &op);
/// Statements as mnemonic lines (DialectText::printStmts).
bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &error);

/// `s` in upper case.
std::string upper(std::string_view s);

/// `s` as a FANUC address (`R100`, `X0000.3`): `out` gets its area and index (in one of the
/// area's ranges), `bit` -1 or the number after the dot (not checked against 0..7). False with
/// `error` set otherwise; `labels`: the unknown-area message lists L and P too.
bool readAddress(std::string_view s, bool labels, Operand &out, int64_t &bit, std::string &error);
/// The ranges of area `a` as messages show them: `R0..R7999, R9000..R9499`.
std::string ranges(Area a);

// ---- mnemonic files (MnemonicFile.cpp, B-66234EN 6.7) ----
/// Where the ladder of a `.pmc` text is and what its symbol sections defined.
struct PmcSource {
  bool hasLadder = true;   ///< false: a mnemonic file without a %@3 section (an error given)
  std::string_view ladder; ///< the mnemonic lines (the whole text of a plain file)
  int32_t firstLine = 1;   ///< the file's line number of the ladder's first line
  bool hasTable = false;   ///< symbols given or a %@2-E section read: names are resolved
  /// Names (upper case) of symbol definitions rejected with an error, and their lines.
  std::map<std::string, int32_t> rejected;
};

/// Split `text` (a plain mnemonic text or a mnemonic file of %@ sections) and read its %@2-E
/// symbol sections into `table` after the `external` symbols (may be null), with located
/// diagnostics for every section and symbol error.
PmcSource readPmcSource(std::string_view text, const SymbolTable *external, SymbolTable &table,
                        Diagnostics &diags);

/// 0..9999 written in decimal as its 4-digit BCD bit pattern (reference 3.2).
inline int32_t toBcd(int64_t v) {
  return static_cast<int32_t>(bcd::encode(static_cast<uint64_t>(v), 4));
}

/// A constant operand `v` located at `at`.
inline Operand konst(int64_t v, SourceLoc at = {}) {
  Operand o;
  o.kind = Operand::Kind::Const;
  o.value = static_cast<int32_t>(v);
  o.loc = at;
  return o;
}

/// Byte `index` of `area` read as `width` bytes (the T / C / R9000 / R9002 operands an
/// instruction implies), located at `at`.
inline Operand implied(Area area, int32_t index, int width, SourceLoc at) {
  Operand o;
  o.kind = Operand::Kind::Reg;
  o.area = area;
  o.index = index;
  o.width = static_cast<uint8_t>(width);
  o.loc = at;
  return o;
}

} // namespace lj::fanuc::detail
