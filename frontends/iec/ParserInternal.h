// The IEC IL parser's class, shared by the files that hold its parts (Parser.cpp: lines,
// statements and the instruction dispatch; ParserSequence.cpp: operands, contacts,
// parentheses, coils and MPS; ParserBlocks.cpp: operation blocks and function blocks;
// ParserFlow.cpp: labels, subroutines, jumps, END, RET and calls). Internal to the front end:
// its interface is FrontEnd.h's parseIl.
#pragma once

#include "frontends/iec/Blocks.h"
#include "frontends/iec/Emitter.h"
#include "frontends/iec/Objects.h"

#include "ir/Diagnostics.h"
#include "ir/Program.h"

#include <cctype>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::iec::detail {

inline std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

inline bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

inline std::string lineText(SourceLoc l) { return "line " + std::to_string(l.line); }

/// Contact forms by modifier: plain, N (negated), R (rising edge), F (falling edge).
enum class Mod : uint8_t { Plain, Not, Rise, Fall };

inline Op loadOp(Mod m) {
  switch (m) {
  case Mod::Not:
    return Op::LoadNot;
  case Mod::Rise:
    return Op::LoadRise;
  case Mod::Fall:
    return Op::LoadFall;
  default:
    return Op::Load;
  }
}

struct Paren {
  Op close;
  SourceLoc loc;
};

struct Relation {
  Operand a, b;
  std::string rel; // < <= > >= = <>
};

/// One IL text -> one ParsedProgram; every problem a located diagnostic.
class IlParser {
public:
  IlParser(ParsedProgram &prog, Diagnostics &diags)
      : prog_(prog), diags_(diags), em_(prog, diags), blocks_(em_, diags) {}
  void run(std::string_view text);

private:
  static constexpr int kMaxErrors = 100;
  static constexpr int32_t kStatementLimit = 10000;

  void error(SourceLoc loc, const char *code, const std::string &msg) {
    diags_.error(loc, code, msg);
  }

  // ---- lines, statements and the instruction dispatch (Parser.cpp)
  /// The block presets (FunctionBlocks::presets) at the start of the init part; statement ids
  /// and comment positions move with them.
  void insertPresets();
  void handleLine(std::string_view line, int32_t lineNo);
  /// The statements from `first` on came from the line `code` (comments blanked): recorded as
  /// written (ir/Program.h WrittenInstr) when the IL printer could not give them back (scratch
  /// bits of N / XOR / OPEN / SHORT / JMPCN / RETCN and the block inputs, END's jump, a block's
  /// run). A line without statements (BLK, OUT_BLK, END_BLK, CONFIG, NOP) goes with the next line
  /// that has statements, which is then recorded as written.
  void record(size_t first, std::string_view code, int32_t line);
  void statement(const std::string &code, int32_t lineNo);
  void instruction(const std::string &mnem, std::optional<char> paren, std::string_view text,
                   SourceLoc loc, SourceLoc opLoc);

  // ---- the sequence: operands, contacts, parentheses, coils, MPS (ParserSequence.cpp)
  /// A statement that needs an open sequence (an accumulator value).
  bool needSequence(SourceLoc loc, const std::string &what);
  /// A statement the seed forbids inside parentheses (L973-976, L1046).
  bool outsideParens(SourceLoc loc, const std::string &what);
  /// The end of a sequence (a new LD, a label, a header, the end): everything must be closed.
  void closeSequence(SourceLoc loc, const std::string &where);
  void startSequence(SourceLoc loc, const std::string &mnem);
  std::optional<Object> object(std::string_view text, SourceLoc loc, const std::string &mnem);
  static bool isBitObject(ObjClass c);
  /// A test operand of `mnem` with modifier `mod`; `immediate`: 0/1 accepted.
  std::optional<Object> testOperand(std::string_view text, SourceLoc loc, const std::string &mnem,
                                    Mod mod, bool immediate);
  /// `[a REL b]`, for LD/LDN/AND/ANDN and AND([ / OR([.
  std::optional<Relation> comparison(std::string_view text, SourceLoc loc, const std::string &mnem);
  /// A word operand or constant; `dest`: must be a writable word.
  std::optional<Operand> wordOperand(std::string_view t, SourceLoc loc, const std::string &mnem,
                                     bool dest);
  /// Push (LD) or combine with AND (AND) the comparison, negated for LDN / ANDN.
  void emitComparison(const Relation &r, bool negated, bool push, SourceLoc loc);
  void closeParen(SourceLoc loc);
  /// Push the first operand of a sequence or a parenthesis: `mnem` with modifier `mod`.
  void pushTest(const std::string &mnem, Mod mod, std::string_view text, SourceLoc loc,
                SourceLoc opLoc, bool comparisonOk);
  void nonReversible(SourceLoc loc, const std::string &mnem);
  void combine(const std::string &fam, Mod mod, const std::string &mnem, std::string_view text,
               SourceLoc loc, SourceLoc opLoc);
  void coil(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc);
  void branch(const std::string &mnem, std::string_view text, SourceLoc loc);
  /// The system bits of the profile's table (%S0, %S1, %S4..%S7, %S13).
  static bool runtimeBit(int32_t n);
  static std::string parenName(const Paren &p) { return p.close == Op::AndBlock ? "AND(" : "OR("; }

  // ---- operation blocks and function blocks (ParserBlocks.cpp)
  static bool isPreset(const Operand &o);
  void operationBlock(std::string_view text, SourceLoc loc);
  /// The instructions allowed between BLK and OUT_BLK besides the block's inputs: tests only
  /// (modicon-neza.md 3.1, L1244-1246).
  static bool testInstruction(const std::string &m);
  void inputSection(SourceLoc loc, const std::string &what);
  /// Not inside a BLK structure at all (jumps, calls, END, other blocks).
  bool outsideBlock(SourceLoc loc, const std::string &what);
  /// CONFIG, BLK, OUT_BLK, END_BLK, the inputs IN / CU / CD / R / S; false when `mnem` is none.
  bool blockInstruction(const std::string &mnem, std::string_view text, SourceLoc loc,
                        SourceLoc opLoc);
  /// The instruction form `IN %TMi`, `CU %Ci`, `R %Ci`... (not reversible, modicon-neza.md 9 rule
  /// 2).
  void directBlock(const std::string &mnem, const Object &blk, SourceLoc loc, SourceLoc opLoc);

  // ---- program parts and flow: labels, subroutines, jumps, END, RET, calls (ParserFlow.cpp)
  /// Code after END outside a subroutine.
  void afterMain(SourceLoc loc);
  void finishMain(SourceLoc loc);
  void header(std::string_view name, SourceLoc loc);
  std::optional<Operand> label(std::string_view text, SourceLoc opLoc, const std::string &mnem);
  void jump(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc);
  void end(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc);
  void ret(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc);
  void call(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc);

  ParsedProgram &prog_;
  Diagnostics &diags_;
  Emitter em_;
  FunctionBlocks blocks_;
  int32_t configLines_ = 0;
  std::vector<Paren> parens_;
  std::vector<SourceLoc> mps_;
  bool seq_ = false;
  bool mainDone_ = false, mainEnded_ = false, afterEndReported_ = false;
  int32_t sub_ = -1;
  int32_t stmtCount_ = 0;
  bool inComment_ = false;
  SourceLoc commentLoc_;
  std::string pendingWritten_;  ///< lines without statements so far (record())
  int32_t pendingLine_ = 0;     ///< the line of the first of them
  size_t lastFirst_ = SIZE_MAX; ///< the first statement of the last line that had statements
  std::string lastText_;        ///< that line as written
};

} // namespace lj::iec::detail
