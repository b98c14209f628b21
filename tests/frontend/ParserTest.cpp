// Lexer/parser unit tests: statement syntax, operands, constants and per-operand checks
// (DIALECT.md 1-2, docs/dialect-notes.md "Text").
#include "FrontEndTestUtil.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

using test::parse;

const Stmt &only(const test::Parsed &p) {
  EXPECT_EQ(p.prog.stmts.size(), 1u) << p.diags;
  static const Stmt kEmpty{};
  return p.prog.stmts.empty() ? kEmpty : p.prog.stmts[0];
}

// dialect-notes "Text": `;` and `//` start a comment anywhere; blank lines are ignored.
TEST(Parser, CommentsAndBlankLines) {
  auto p = parse("; header\n\n   \nLD X1.0 ; trailing\n// whole line\nOUT Y0.0// glued\n\t\n");
  ASSERT_EQ(p.errors, 0) << p.diags;
  ASSERT_EQ(p.prog.stmts.size(), 2u);
  EXPECT_EQ(p.prog.stmts[0].op, Op::Load);
  EXPECT_EQ(p.prog.stmts[0].loc.line, 4);
  EXPECT_EQ(p.prog.stmts[1].op, Op::Coil);
  EXPECT_EQ(p.prog.stmts[1].loc.line, 6);
  EXPECT_EQ(formatOperand(p.prog.stmts[1].ops[0]), "Y0.0");
}

// DIALECT.md 2: mnemonics and area letters are case-insensitive; WRT/END1/END2 are aliases.
TEST(Parser, CaseInsensitiveAndAliases) {
  auto p = parse("ld x1.0\nwrt y0.1\niEND\nend1\nEnd2\n1end\n2END\nLdT\n");
  ASSERT_EQ(p.errors, 0) << p.diags;
  ASSERT_EQ(p.prog.stmts.size(), 8u);
  EXPECT_EQ(p.prog.stmts[0].op, Op::Load);
  EXPECT_EQ(p.prog.stmts[0].ops[0].area, Area::Input);
  EXPECT_EQ(p.prog.stmts[1].op, Op::Coil);
  EXPECT_EQ(p.prog.stmts[1].ops[0].area, Area::Output);
  EXPECT_EQ(p.prog.stmts[2].op, Op::EndInit);
  EXPECT_EQ(p.prog.stmts[3].op, Op::EndCyclic);
  EXPECT_EQ(p.prog.stmts[4].op, Op::EndSliced);
  EXPECT_EQ(p.prog.stmts[5].op, Op::EndCyclic);
  EXPECT_EQ(p.prog.stmts[6].op, Op::EndSliced);
  EXPECT_EQ(p.prog.stmts[7].op, Op::LoadTrue);
}

// DIALECT.md 2: operands separated by spaces or tabs; columns are 1-based.
TEST(Parser, OperandsAndColumns) {
  auto p = parse("  ADD\tD0   100\t\tD1\r\n");
  const Stmt &s = only(p);
  EXPECT_EQ(s.op, Op::Add);
  EXPECT_EQ(s.loc.col, 3);
  ASSERT_EQ(s.operandCount, 3);
  EXPECT_EQ(s.ops[0].kind, Operand::Kind::Reg);
  EXPECT_EQ(s.ops[0].area, Area::DWord);
  EXPECT_EQ(s.ops[0].index, 0);
  EXPECT_EQ(s.ops[0].loc.col, 7);
  EXPECT_EQ(s.ops[1].kind, Operand::Kind::Const);
  EXPECT_EQ(s.ops[1].value, 100);
  EXPECT_EQ(s.ops[1].loc.col, 12);
  EXPECT_EQ(s.ops[2].area, Area::DWord);
  EXPECT_EQ(s.ops[2].index, 1);
  EXPECT_EQ(s.ops[2].loc.col, 17);
}

// dialect-notes "Text": leading zeros in addresses and constants (never octal).
TEST(Parser, LeadingZeros) {
  auto p = parse("LD X0010.3\nMOV 007 D05\n");
  ASSERT_EQ(p.errors, 0) << p.diags;
  const Stmt &ld = p.prog.stmts[0];
  EXPECT_EQ(ld.ops[0].kind, Operand::Kind::Bit);
  EXPECT_EQ(ld.ops[0].index, 10);
  EXPECT_EQ(ld.ops[0].bit, 3);
  EXPECT_EQ(p.prog.stmts[1].ops[0].value, 7);
  EXPECT_EQ(p.prog.stmts[1].ops[1].index, 5);
}

// dialect-notes "Text": decimal int32 with sign, 0x hex of at most 32 bits as a bit pattern.
TEST(Parser, Constants) {
  struct Case {
    const char *text;
    int32_t value;
  } cases[] = {{"-5", -5},
               {"+5", 5},
               {"2147483647", INT32_MAX},
               {"-2147483648", INT32_MIN},
               {"0x7fffffff", INT32_MAX},
               {"0xFFFFFFFF", -1},
               {"0x80000000", INT32_MIN},
               {"0x0000000010", 16}};
  for (const Case &c : cases) {
    auto p = parse(std::string("MOV ") + c.text + " D0\n");
    const Stmt &s = only(p);
    EXPECT_EQ(s.ops[0].kind, Operand::Kind::Const) << c.text;
    EXPECT_EQ(s.ops[0].value, c.value) << c.text;
  }
}

TEST(Parser, ConstantErrors) {
  EXPECT_EQ(parse("MOV 2147483648 D0\n").diags,
            "t.stl:1:5: error: constant '2147483648' is outside the int32 range [LJ3009]\n");
  EXPECT_EQ(parse("MOV -2147483649 D0\n").diags,
            "t.stl:1:5: error: constant '-2147483649' is outside the int32 range [LJ3009]\n");
  EXPECT_EQ(parse("MOV 0x100000000 D0\n").diags,
            "t.stl:1:5: error: hex constant '0x100000000' has more than 32 bits [LJ3008]\n");
  EXPECT_EQ(parse("MOV 12ab D0\n").diags, "t.stl:1:5: error: malformed constant '12ab' [LJ3002]\n");
  EXPECT_EQ(parse("MOV 0xG D0\n").diags, "t.stl:1:5: error: malformed constant '0xG' [LJ3002]\n");
  EXPECT_EQ(parse("MOV 99999999999999999999999999 D0\n").diags,
            "t.stl:1:5: error: constant '99999999999999999999999999' is outside the int32 "
            "range [LJ3009]\n");
}

// DIALECT.md 1: widths give the bit ranges; the table's areas per operand position.
TEST(Parser, BitRangesPerArea) {
  auto ok = parse("LD X512.7\nLD F3119.15\nLD G0.15\nLD W199.15\nLD D99.31\nLD B49.31\n"
                  "LD P199.31\nLD T427.0\nLD C300.0\nLD R399.7\nOUT W1.15\n");
  EXPECT_EQ(ok.errors, 0) << ok.diags;
  EXPECT_EQ(ok.prog.stmts.size(), 11u);
  EXPECT_EQ(parse("LD Y1.8\n").diags,
            "t.stl:1:4: error: bit number 8 out of range in 'Y1.8' (Y has bits 0..7) [LJ3014]\n");
  EXPECT_EQ(
      parse("LD W1.16\n").diags,
      "t.stl:1:4: error: bit number 16 out of range in 'W1.16' (W has bits 0..15) [LJ3014]\n");
  EXPECT_EQ(
      parse("LD D1.32\n").diags,
      "t.stl:1:4: error: bit number 32 out of range in 'D1.32' (D has bits 0..31) [LJ3014]\n");
  // dialect-notes "Function blocks": any bit of T/C other than .0 is an error.
  EXPECT_EQ(parse("LD T5.1\n").diags,
            "t.stl:1:4: error: bit number 1 out of range in 'T5.1' (T has only bit .0) [LJ3014]\n");
}

TEST(Parser, AddressRanges) {
  EXPECT_EQ(parse("LD X513.0\n").diags,
            "t.stl:1:4: error: address 'X513.0' out of range (X0..X512) [LJ3012]\n");
  EXPECT_EQ(parse("LD T200.0\n").diags,
            "t.stl:1:4: error: address 'T200.0' out of range (T0..T127, T300..T427) [LJ3012]\n");
  EXPECT_EQ(parse("JMP L10000\n").diags,
            "t.stl:1:5: error: address 'L10000' out of range (L0..L9999) [LJ3012]\n");
  EXPECT_EQ(parse("CALL S512\n").diags,
            "t.stl:1:6: error: address 'S512' out of range (S0..S511) [LJ3012]\n");
  EXPECT_EQ(parse("MOV D100 D0\n").diags,
            "t.stl:1:5: error: address 'D100' out of range (D0..D99) [LJ3012]\n");
}

// DIALECT.md 1: writes to read-only areas and areas an instruction does not allow.
TEST(Parser, AreaRules) {
  EXPECT_EQ(parse("OUT X1.0\n").diags,
            "t.stl:1:5: error: X1.0 is read-only; OUT cannot write its coil (writable: Y, G, R, "
            "W, D or B) [LJ3010]\n");
  EXPECT_EQ(parse("MOV 1 P3\n").diags,
            "t.stl:1:7: error: P3 is read-only; MOV cannot write its destination (writable: Y, "
            "G, R, W, D or B) [LJ3010]\n");
  // dialect-notes: T and C are not numeric operands.
  EXPECT_EQ(parse("ADD T1 1 D0\n").diags,
            "t.stl:1:5: error: area T is not allowed as augend of ADD (allowed: X, Y, F, G, R, "
            "W, D, B or P) [LJ3011]\n");
  EXPECT_EQ(parse("JMP R5\n").diags,
            "t.stl:1:5: error: area R is not allowed as label of JMP (allowed: L) [LJ3011]\n");
  EXPECT_EQ(parse("LD L5.0\n").diags,
            "t.stl:1:4: error: area L is not allowed as contact of LD (allowed: X, Y, F, G, R, "
            "W, D, B, P, T or C) [LJ3011]\n");
}

TEST(Parser, OperandKinds) {
  EXPECT_EQ(parse("OUT 5\n").diags,
            "t.stl:1:5: error: OUT expects a bit address (like X1.0) as coil, got constant "
            "'5' [LJ3013]\n");
  EXPECT_EQ(parse("LD D5\n").diags,
            "t.stl:1:4: error: LD expects a bit address (like X1.0) as contact, got register "
            "'D5' [LJ3013]\n");
  EXPECT_EQ(parse("ADD X1.0 1 D0\n").diags,
            "t.stl:1:5: error: ADD expects a register or constant as augend, got bit address "
            "'X1.0' [LJ3017]\n");
  EXPECT_EQ(parse("ADD 1 1 5\n").diags,
            "t.stl:1:9: error: ADD expects a register as destination, got constant '5' [LJ3015]\n");
  EXPECT_EQ(
      parse("TMRB D1 0 100\n").diags,
      "t.stl:1:6: error: TMRB expects a constant as timer number, got register 'D1' [LJ3017]\n");
  EXPECT_EQ(parse("TMRB 1 4 100\n").diags,
            "t.stl:1:8: error: constant '4' out of range for time unit of TMRB (0..3) [LJ3016]\n");
  EXPECT_EQ(
      parse("JMP 5\n").diags,
      "t.stl:1:5: error: JMP expects a label (L0..L9999) as label, got constant '5' [LJ3015]\n");
  EXPECT_EQ(parse("LD Q5.0\n").diags,
            "t.stl:1:4: error: unknown area letter 'Q' in 'Q5.0' [LJ3006]\n");
  EXPECT_EQ(parse("LD X1.0.0\n").diags, "t.stl:1:4: error: malformed address 'X1.0.0' [LJ3007]\n");
  EXPECT_EQ(parse("LD X.1\n").diags, "t.stl:1:4: error: malformed address 'X.1' [LJ3007]\n");
  EXPECT_EQ(parse("LD #1\n").diags, "t.stl:1:4: error: malformed operand '#1' [LJ3005]\n");
}

TEST(Parser, OperandCount) {
  EXPECT_EQ(parse("OUT\n").diags, "t.stl:1:1: error: OUT takes 1 operand (coil), got 0 [LJ3003]\n");
  EXPECT_EQ(parse("LDT X1.0\n").diags, "t.stl:1:5: error: LDT takes no operands, got 1 [LJ3003]\n");
  EXPECT_EQ(
      parse("ADD D0 1 D1 D2\n").diags,
      "t.stl:1:13: error: ADD takes 3 operands (augend, addend, destination), got 4 [LJ3003]\n");
}

// DIALECT.md 6: all errors are reported, bad lines dropped, parsing continues.
TEST(Parser, BadLinesDroppedParsingContinues) {
  auto p = parse("LD X1.0\nFOO\nOUT Y0.0\nLD X1.8 X1.9\nLD X1.8\nOUT Y0.1\n");
  EXPECT_EQ(p.errors, 3) << p.diags;
  ASSERT_EQ(p.prog.stmts.size(), 3u);
  EXPECT_EQ(p.prog.stmts[2].loc.line, 6);
  EXPECT_EQ(p.diags,
            "t.stl:2:1: error: unknown mnemonic 'FOO' [LJ3001]\n"
            "t.stl:4:9: error: LD takes 1 operand (contact), got 2 [LJ3003]\n"
            "t.stl:5:4: error: bit number 8 out of range in 'X1.8' (X has bits 0..7) [LJ3014]\n");
}

// A dropped line with a known mnemonic is remembered (position and op) so the verifier can
// keep its stack effect; unknown mnemonics are not.
TEST(Parser, DroppedLinesRecorded) {
  auto p = parse("LD X1.0\nLD X1.8\nFOO\nOUT Y0.0\n");
  ASSERT_EQ(p.prog.dropped.size(), 1u);
  EXPECT_EQ(p.prog.dropped[0].before, 1);
  EXPECT_EQ(p.prog.dropped[0].op, Op::Load);
}

// Several bad operands on one line are all reported.
TEST(Parser, AllOperandErrorsOfALine) {
  auto p = parse("ADD X1.0 T5 P2\n");
  EXPECT_EQ(p.errors, 3) << p.diags;
}

// Any bytes: the message quotes them escaped and cut, never raw.
TEST(Parser, BinaryBytesInMessages) {
  std::string text = std::string("L\x01\xff") + '\0' + "D X1.0\n";
  auto p = parse(text);
  EXPECT_EQ(p.diags, "t.stl:1:1: error: unknown mnemonic 'L\\x01\\xFF\\x00D' [LJ3001]\n");
  auto longTok = parse(std::string(100, 'A') + "\n");
  EXPECT_EQ(longTok.diags,
            "t.stl:1:1: error: unknown mnemonic '" + std::string(40, 'A') + "...' [LJ3001]\n");
}

// A UTF-8 byte-order mark does not belong to the first mnemonic.
TEST(Parser, ByteOrderMark) {
  auto p = parse("\xEF\xBB\xBFLD X1.0\n");
  EXPECT_EQ(p.errors, 0) << p.diags;
  EXPECT_EQ(only(p).loc.col, 1);
}

TEST(Parser, NoTrailingNewlineAndCrLf) {
  auto p = parse("LD X1.0\r\nOUT Y0.0");
  EXPECT_EQ(p.errors, 0) << p.diags;
  EXPECT_EQ(p.prog.stmts.size(), 2u);
}

} // namespace
} // namespace lj
