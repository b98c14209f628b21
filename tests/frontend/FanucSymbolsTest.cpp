// FANUC symbols and comments (docs/fanuc-pmc.md "Symbols and comments"): the LADDER-III mnemonic
// file's sections (%@A .. %@E, %@2-E CSV symbols, %@3 ladder, `%` closing), the symbol rules with
// their located messages, and names in operands resolved exactly like the addresses they stand
// for. One test per rule.
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/hnc8/Address.h"
#include "pipeline/Compile.h"
#include "tests/frontend/FanucDiags.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace lj {
namespace {

std::string diags(const std::string &text) { return test::fanucDiags(text); }

struct Parsed {
  ParsedProgram prog;
  std::string diags;
};

Parsed parse(const std::string &text, const SymbolTable *external = nullptr) {
  Diagnostics d("t.pmc");
  Parsed r{fanuc::parsePmc(text, "t.pmc", d, external), ""};
  r.diags = d.render();
  return r;
}

/// A mnemonic file: `symbols` (CSV rows) in a %@2-E section, `ladder` in a %@3 section.
std::string file(const std::string &symbols, const std::string &ladder,
                 const std::string &header = "%@2-E(SYM=1 ADR=2 CM1=3 CM2=4)") {
  return header + "\n" + symbols + "%\n%@3\n" + ladder + "%\n";
}

constexpr const char *kSymbols = "ESP_OK,X0000.0,E-STOP CHAIN,1 = OK\n"
                                 "KEY,X0.1,COOLANT KEY,\n"
                                 "MCODE,F0010,M CODE,BINARY\n"
                                 "PUMP,Y0.0,,\n"
                                 "FLAG,R0001.2\n"
                                 "WORD,D0100,SET WORD,\n"
                                 "COUNT,D102,,\n";

/// Every statement of `a` has the op and the operands of `b`'s (kinds, areas, numbers, bits,
/// widths, constants); `a`'s operands may be written as symbols.
void expectSameStatements(const std::vector<Stmt> &a, const std::vector<Stmt> &b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].op, b[i].op) << i;
    ASSERT_EQ(a[i].operandCount, b[i].operandCount) << i;
    for (int k = 0; k < a[i].operandCount; ++k) {
      const Operand &x = a[i].ops[k], &y = b[i].ops[k];
      EXPECT_EQ(fanuc::formatOperand(x), fanuc::formatOperand(y)) << i << " " << k;
      EXPECT_EQ(x.kind, y.kind) << i << " " << k;
      EXPECT_EQ(x.width, y.width) << i << " " << k;
      EXPECT_EQ(x.bcd, y.bcd) << i << " " << k;
    }
  }
}

// ---- the file ----

TEST(FanucSymbols, PlainFilesAreReadAsBefore) {
  EXPECT_EQ(diags("RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n"), "");
  Parsed p = parse("RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n");
  EXPECT_TRUE(p.prog.symbols.empty());
  EXPECT_EQ(p.prog.stmts[0].ops[0].symbol, -1);
  // Without a symbol table a name is no address, as before.
  EXPECT_EQ(diags("RD KEY\nEND1\nEND2\nEND\n"),
            "t.pmc:1:4: error: unknown address 'KEY' (areas: X Y F G R E A T C K D; labels L, "
            "subroutines P) [LJ4017]\n");
  // A section line among plain mnemonic lines: the file does not start with a section.
  EXPECT_EQ(diags("RD X0.0\n%@3\nEND1\nEND2\nEND\n"),
            "t.pmc:2:1: error: '%@3' among mnemonic lines: a mnemonic file starts with %@A or a "
            "section header (%@3 the ladder, %@2-E the symbols), docs/fanuc-pmc.md [LJ4007]\n");
}

TEST(FanucSymbols, SectionsAndLineNumbersOfTheFile) {
  const std::string text = file(kSymbols, "RD KEY\nWRT PUMP\nEND1\nEND2\nEND\n");
  Parsed p = parse(text);
  EXPECT_EQ(p.diags, "");
  ASSERT_EQ(p.prog.stmts.size(), 4u);
  EXPECT_EQ(p.prog.stmts[0].loc.line, 11); // the file's line, not the section's
  EXPECT_EQ(p.prog.stmts[1].loc.line, 12);
  // A ladder error is reported at the file's line too.
  EXPECT_EQ(diags(file(kSymbols, "RD KEY\nAND.STK\nEND1\nEND2\nEND\n")),
            "t.pmc:12:1: error: AND.STK needs two logic lines (ST1 and ST0), found 1 [LJ4034]\n");
  // Comment lines in the ladder section stay comments of the program at their lines.
  Parsed c = parse(file("KEY,X0.1\n", "; the key\nRD KEY\nWRT Y0.0\nEND1\nEND2\nEND\n"));
  EXPECT_EQ(c.diags, "");
  ASSERT_EQ(c.prog.comments.size(), 1u);
  EXPECT_EQ(c.prog.comments[0].line, 5);
  EXPECT_EQ(c.prog.comments[0].text, "the key");
}

TEST(FanucSymbols, SymbolsMayFollowTheLadder) {
  const std::string text = "%@3\nRD KEY\nWRT PUMP\nEND1\nEND2\nEND\n%\n"
                           "%@2-E(SYM=1 ADR=2 CM1=3 CM2=4)\nKEY,X0.1,,\nPUMP,Y0.0,,\n%\n";
  EXPECT_EQ(diags(text), "");
}

TEST(FanucSymbols, AllFormatWrapper) {
  const std::string body = file("KEY,X0.1\n", "RD KEY\nWRT Y0.0\nEND1\nEND2\nEND\n");
  EXPECT_EQ(diags("%@A\n" + body + "%@E\n"), "");
  // Blank lines and CR LF line ends around it.
  EXPECT_EQ(diags("\r\n%@A\r\n%@3\r\nRD X0.0\r\nWRT Y0.0\r\nEND1\r\nEND2\r\nEND\r\n%\r\n%@E\r\n"),
            "");
  // A header also ends the section open before it.
  EXPECT_EQ(diags("%@A\n%@2-E\nKEY,X0.1\n%@3\nRD KEY\nWRT Y0.0\nEND1\nEND2\nEND\n%@E\n"), "");
  EXPECT_EQ(
      diags(body + "%@E\n"),
      "t.pmc:11:1: error: %@E without %@A (%@E ends ALL-format data that %@A starts) [LJ4089]\n");
  EXPECT_EQ(diags("%@A\n" + body),
            "t.pmc:11:1: error: %@A (line 1) without %@E at the end of the file [LJ4084]\n");
  EXPECT_EQ(diags(body + "%@A\n"),
            "t.pmc:11:1: error: %@A must be the first line of the file (it opens ALL-format "
            "data) [LJ4088]\n");
  EXPECT_EQ(diags("%@A\n" + body + "%@E\nRD X0.0\n"),
            "t.pmc:13:1: error: text after %@E (the end of the mnemonic file) [LJ4005]\n");
}

TEST(FanucSymbols, SectionStructureErrors) {
  const std::string ladder = "%@3\nRD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n%\n";
  EXPECT_EQ(diags(ladder + "RD X0.1\n"),
            "t.pmc:8:1: error: text outside a section: 'RD X0.1' (mnemonic lines belong in a %@3 "
            "section, symbols in a %@2-E section) [LJ4004]\n");
  EXPECT_EQ(
      diags(ladder + "%\n"),
      "t.pmc:8:1: error: '%' closes no section (it ends the section a %@ line opens) [LJ4086]\n");
  EXPECT_EQ(diags("%@3\nRD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n"),
            "t.pmc:1:1: error: section %@3 is not closed: the file ends inside it (a line "
            "holding only '%' ends a section) [LJ4083]\n");
  EXPECT_EQ(diags("%@2-E\nKEY,X0.1\n%\n"),
            "t.pmc:1:1: error: this mnemonic file has no ladder section (%@3 holds the mnemonic "
            "lines, docs/fanuc-pmc.md) [LJ4085]\n");
  EXPECT_EQ(diags(ladder + "%@3\nEND1\n%\n"),
            "t.pmc:8:1: error: a second ladder section %@3 (the first is on line 1) [LJ4090]\n");
  EXPECT_EQ(diags(ladder + "%X\n"),
            "t.pmc:8:1: error: bad section line '%X': a section starts with %@ and its code "
            "(%@3, %@2-E), a line holding only '%' ends it [LJ4087]\n");
}

TEST(FanucSymbols, OtherSectionsAreSkippedWithOneWarningEach) {
  const std::string text = "%@A\n"
                           "%@0\nPARAM LINE\n%\n"
                           "%@1\nTITLE LINE\n%\n"
                           "%@2\nFORMAT A LINE\n%\n"
                           "%@2-C\nFORMAT C LINE\n%\n"
                           "%@3\nRD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n%\n"
                           "%@4\nA0.0 MESSAGE ONE\nA0.1 MESSAGE TWO\n%\n"
                           "%@5\nIO LINE\n%\n"
                           "%@9\nX\n%\n"
                           "%@E\n";
  EXPECT_EQ(
      diags(text),
      "t.pmc:2:1: warning: section %@0 (system parameters) is not read by ladderjit [LJ4091]\n"
      "t.pmc:5:1: warning: section %@1 (title data) is not read by ladderjit [LJ4091]\n"
      "t.pmc:8:1: warning: section %@2 (symbol and comment data, FORMAT-A/B; ladderjit reads "
      "symbols from a %@2-E (CSV) section) is not read by ladderjit [LJ4091]\n"
      "t.pmc:11:1: warning: section %@2-C (symbol and comment data, FORMAT-C; ladderjit reads "
      "symbols from a %@2-E (CSV) section) is not read by ladderjit [LJ4091]\n"
      "t.pmc:21:1: warning: section %@4 (message data) is not read by ladderjit [LJ4091]\n"
      "t.pmc:25:1: warning: section %@5 (I/O module data) is not read by ladderjit [LJ4091]\n"
      "t.pmc:28:1: warning: section %@9 is not read by ladderjit [LJ4091]\n");
  Diagnostics d("t.pmc");
  EXPECT_TRUE(pipeline::compilePmc(text, "t.pmc", VerifyOptions{}, d, nullptr)) << d.render();
}

// ---- the %@2-E option ----

TEST(FanucSymbols, OptionGivesTheColumns) {
  // Columns in another order, the option omitted (the defaults), absent and empty columns.
  Parsed p = parse(file("RED,Y0.3,LAMP\n,,,\n", "RD X0.0\nWRT LAMP\nEND1\nEND2\nEND\n",
                        "%@2-E(CM1=1 ADR=2 SYM=3)"));
  EXPECT_EQ(p.diags, "");
  p = parse(file("LAMP,Y0.3,RED LAMP,ON = ALARM\n", "RD X0.0\nWRT LAMP\nEND1\nEND2\nEND\n"));
  EXPECT_EQ(p.diags, "");
  p = parse(
      file("CM,Y0.3,LAMP\n", "RD X0.0\nWRT LAMP\nEND1\nEND2\nEND\n", "%@2-E(CM1=1 ADR=2 SYM=3)"));
  EXPECT_EQ(p.diags, "");
  ASSERT_EQ(p.prog.symbols.size(), 1u);
  EXPECT_EQ(p.prog.symbols[0].name, "LAMP");
  EXPECT_EQ(p.prog.symbols[0].address, "Y0.3");
  EXPECT_EQ(p.prog.symbols[0].comment, "CM");
  p = parse(file("LAMP,Y0.3\nKEY,X0.1,,\n", "RD KEY\nWRT LAMP\nEND1\nEND2\nEND\n", "%@2-E"));
  EXPECT_EQ(p.diags, "");
  ASSERT_EQ(p.prog.symbols.size(), 2u);
  EXPECT_EQ(p.prog.symbols[1].comment, "");
  // Blank and comma-only rows are nothing.
  EXPECT_EQ(diags(file("\n,,,\nKEY,X0.1\n", "RD KEY\nWRT Y0.0\nEND1\nEND2\nEND\n")), "");
}

TEST(FanucSymbols, OptionErrors) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  auto with = [&](const std::string &header) { return diags(file("", ladder, header)); };
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=2 CMT=3)"), "t.pmc:1:19: error: unknown key 'CMT' in the %@2-E "
                                              "option (keys: SYM ADR CM1 CM2) [LJ4096]\n");
  EXPECT_EQ(with("%@2-E(SYM=0 ADR=2)"),
            "t.pmc:1:11: error: bad column number '0' for SYM (1..99) [LJ4097]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=x)"),
            "t.pmc:1:17: error: bad column number 'x' for ADR (1..99) [LJ4097]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=100)"),
            "t.pmc:1:17: error: bad column number '100' for ADR (1..99) [LJ4097]\n");
  // Many digits are a bad column, not an int overflow (found by fuzz_pmc under UBSan).
  EXPECT_EQ(
      with("%@2-E(SYM=1 ADR=99999999999999999999)"),
      "t.pmc:1:17: error: bad column number '99999999999999999999' for ADR (1..99) [LJ4097]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=2 SYM=3)"),
            "t.pmc:1:19: error: SYM is given twice in the %@2-E option [LJ4098]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=1)"),
            "t.pmc:1:17: error: column 1 is given to both SYM and ADR [LJ4099]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 CM1=2)"),
            "t.pmc:1:6: error: the %@2-E option gives no ADR column (a symbol needs SYM and "
            "ADR) [LJ4100]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=2"),
            "t.pmc:1:6: error: the %@2-E option has no closing ')' [LJ4093]\n");
  EXPECT_EQ(with("%@2-E(SYM=1 ADR=2) X"),
            "t.pmc:1:20: error: text after the %@2-E option: 'X' [LJ4094]\n");
  EXPECT_EQ(with("%@2-E(SYM ADR=2)"),
            "t.pmc:1:7: error: expected KEY=COLUMN in the %@2-E option, got 'SYM' [LJ4095]\n");
  // The section is not read after such an error: its rows give no further errors.
  EXPECT_EQ(diags(file("1BAD,Q0\n", ladder, "%@2-E(SYM=1 ADR=2 CMT=3)")),
            "t.pmc:1:19: error: unknown key 'CMT' in the %@2-E option (keys: SYM ADR CM1 CM2) "
            "[LJ4096]\n");
}

// ---- the symbol rules ----

TEST(FanucSymbols, NameRules) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  EXPECT_EQ(diags(file(std::string(40, 'A') + ",X0.1\n_x1,X0.2\n主轴,X0.3\n", ladder)), "");
  EXPECT_EQ(diags(file(std::string(41, 'B') + ",X0.1\n", ladder)),
            "t.pmc:2:1: error: symbol name '" + std::string(41, 'B') +
                "' is longer than 40 bytes [LJ4006]\n");
  EXPECT_EQ(diags(file("R100,X0.1\n", ladder)),
            "t.pmc:2:1: error: bad symbol name 'R100': a name starts with a letter, '_' or a "
            "non-ASCII character, continues with letters, digits, '_' or non-ASCII characters, "
            "and is not an address like X10 [LJ4006]\n");
  EXPECT_EQ(diags(file("X0,X0.1\n", ladder)),
            "t.pmc:2:1: error: bad symbol name 'X0': a name starts with a letter, '_' or a "
            "non-ASCII character, continues with letters, digits, '_' or non-ASCII characters, "
            "and is not an address like X10 [LJ4006]\n");
  EXPECT_EQ(diags(file("A-B,X0.1\n", ladder)),
            "t.pmc:2:1: error: bad symbol name 'A-B': a name starts with a letter, '_' or a "
            "non-ASCII character, continues with letters, digits, '_' or non-ASCII characters, "
            "and is not an address like X10 [LJ4006]\n");
}

TEST(FanucSymbols, NamesAreUniqueCaseInsensitively) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  EXPECT_EQ(diags(file("Key,X0.1\nKEY,X0.2\n", ladder)),
            "t.pmc:3:1: error: duplicate symbol 'KEY' (already defined on line 2 as 'Key'; names "
            "are case-insensitive) [LJ4101]\n");
  // Across two %@2-E sections too.
  EXPECT_EQ(diags("%@2-E\nKEY,X0.1\n%\n%@2-E\n key ,X0.2\n%\n%@3\n" + ladder + "%\n"),
            "t.pmc:5:2: error: duplicate symbol 'key' (already defined on line 2 as 'KEY'; names "
            "are case-insensitive) [LJ4101]\n");
}

TEST(FanucSymbols, AddressRules) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  Parsed p = parse(file("A,f0000.0\nB,R0100\nC,D09999\nD,R9091.6\nE,e5.7\n", ladder));
  EXPECT_EQ(p.diags, "");
  ASSERT_EQ(p.prog.symbols.size(), 5u);
  EXPECT_EQ(p.prog.symbols[0].address, "F0.0"); // canonical
  EXPECT_EQ(p.prog.symbols[1].address, "R100");
  EXPECT_EQ(p.prog.symbols[2].address, "D9999");
  EXPECT_EQ(p.prog.symbols[3].address, "R9091.6");
  EXPECT_EQ(p.prog.symbols[4].address, "E5.7");
  // Each bad address: the row, and the message at its ADR column (line 2, column 3).
  const std::pair<const char *, const char *> bad[] = {
      {"A,X500.0", "address 'X500.0' out of range (X0..X127, X200..X327)"},
      {"A,X0.8", "bit number 8 out of range in 'X0.8' (bits 0..7)"},
      {"A,Q0.0", "unknown address 'Q0.0' (areas: X Y F G R E A T C K D)"},
      {"A,X0.", "malformed address 'X0.'"},
      {"A,L5", "'L5' is a label: a symbol names a bit or byte address (labels and subroutines "
               "are not symbols)"},
      {"A,P1", "'P1' is a subroutine: a symbol names a bit or byte address (labels and "
               "subroutines are not symbols)"},
  };
  for (const auto &[row, msg] : bad)
    EXPECT_EQ(diags(file(std::string(row) + "\n", ladder)),
              std::string("t.pmc:2:3: error: symbol 'A': ") + msg + " [LJ4006]\n");
  EXPECT_EQ(diags(file("A,,LAMP\n", ladder)),
            "t.pmc:2:1: error: symbol 'A' has no address (column ADR = 2 is empty) [LJ4006]\n");
}

TEST(FanucSymbols, CommentsAreJoined) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  Parsed p = parse(
      file("A,X0.1,ONE,TWO\nB,X0.2,ONE,\nC,X0.3,,TWO\nD,X0.4\nE,X0.5, ONE ,  TWO \n", ladder));
  EXPECT_EQ(p.diags, "");
  ASSERT_EQ(p.prog.symbols.size(), 5u);
  EXPECT_EQ(p.prog.symbols[0].comment, "ONE / TWO");
  EXPECT_EQ(p.prog.symbols[1].comment, "ONE");
  EXPECT_EQ(p.prog.symbols[2].comment, "TWO");
  EXPECT_EQ(p.prog.symbols[3].comment, "");
  EXPECT_EQ(p.prog.symbols[4].comment, "ONE / TWO");
  // At most 255 bytes (the 0i-D extended comment), CM1 / CM2 joined.
  EXPECT_EQ(diags(file("A,X0.1," + std::string(255, 'c') + "\n", ladder)), "");
  EXPECT_EQ(diags(file("A,X0.1," + std::string(256, 'c') + "\n", ladder)),
            "t.pmc:2:8: error: symbol 'A': comment longer than 255 bytes [LJ4006]\n");
  EXPECT_EQ(
      diags(file("A,X0.1," + std::string(200, 'c') + "," + std::string(60, 'd') + "\n", ladder)),
      "t.pmc:2:8: error: symbol 'A': comment longer than 255 bytes [LJ4006]\n");
}

TEST(FanucSymbols, RowsWithoutANameGiveOneWarningPerSection) {
  const std::string ladder = "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n";
  Parsed p = parse(file(",X0.1,E-STOP,\nKEY,X0.2\n,X0.3,DOOR,\n", ladder));
  EXPECT_EQ(p.diags,
            "t.pmc:2:2: warning: 2 rows of section %@2-E give an address no symbol "
            "name: ladderjit keeps only named symbols, their comments are not shown [LJ4092]\n");
  EXPECT_EQ(p.prog.symbols.size(), 1u);
}

// ---- names in the ladder ----

TEST(FanucSymbols, NamesInBitByteAndFunctionalOperands) {
  const std::string named = "RD ESP_OK\n"
                            "AND.NOT KEY\n"
                            "WRT PUMP\n"
                            "SET FLAG\n"
                            "END1\n"
                            "RD ESP_OK\n"
                            "EQB MCODE 8\n" // a byte operand
                            "WRT FLAG\n"
                            "RD ESP_OK\n"
                            "MOVW WORD COUNT\n" // two bytes from a symbol's address
                            "RD KEY\n"
                            "SUB 24\n" // parameters on (PRM) lines
                            "(PRM) 1\n"
                            "(PRM) 500\n"
                            "WRT.NOT FLAG\n"
                            "RD KEY\n"
                            "RD.STK ESP_OK\n"
                            "ADDB 2 WORD 5 COUNT\n"
                            "END2\n"
                            "END\n";
  const std::string plain = "RD X0.0\n"
                            "AND.NOT X0.1\n"
                            "WRT Y0.0\n"
                            "SET R1.2\n"
                            "END1\n"
                            "RD X0.0\n"
                            "EQB F10 8\n"
                            "WRT R1.2\n"
                            "RD X0.0\n"
                            "MOVW D100 D102\n"
                            "RD X0.1\n"
                            "SUB 24\n"
                            "(PRM) 1\n"
                            "(PRM) 500\n"
                            "WRT.NOT R1.2\n"
                            "RD X0.1\n"
                            "RD.STK X0.0\n"
                            "ADDB 2 D100 5 D102\n"
                            "END2\n"
                            "END\n";
  Diagnostics dn("t.pmc"), dp("t.pmc");
  std::optional<VerifiedProgram> n =
      pipeline::compilePmc(file(kSymbols, named), "t.pmc", VerifyOptions{}, dn, nullptr);
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(plain, "t.pmc", VerifyOptions{}, dp, nullptr);
  ASSERT_TRUE(n) << dn.render();
  ASSERT_TRUE(p) << dp.render();
  expectSameStatements(n->stmts, p->stmts);
  EXPECT_EQ(n->slices.size(), p->slices.size());
  EXPECT_EQ(n->rungs.size(), p->rungs.size());
}

TEST(FanucSymbols, OperandRecordsItsSymbol) {
  Parsed p = parse(file(kSymbols, "RD KEY\nEQB MCODE 8\nWRT X0.0\nEND1\nEND2\nEND\n"));
  ASSERT_EQ(p.diags, "t.pmc:13:5: error: 'X0.0' is read-only (X is written by the machine or the "
                     "CNC) [LJ4001]\n");
  ASSERT_GE(p.prog.stmts.size(), 2u);
  ASSERT_EQ(p.prog.symbols.size(), 7u);
  const Operand &key = p.prog.stmts[0].ops[0];
  ASSERT_GE(key.symbol, 0);
  EXPECT_EQ(p.prog.symbols[static_cast<size_t>(key.symbol)].name, "KEY");
  EXPECT_EQ(p.prog.symbols[static_cast<size_t>(key.symbol)].comment, "COOLANT KEY");
  const Operand &mcode = p.prog.stmts[1].ops[0];
  ASSERT_GE(mcode.symbol, 0);
  EXPECT_EQ(p.prog.symbols[static_cast<size_t>(mcode.symbol)].name, "MCODE");
  EXPECT_EQ(p.prog.symbols[static_cast<size_t>(mcode.symbol)].comment, "M CODE / BINARY");
  EXPECT_EQ(p.prog.stmts[1].ops[1].symbol, -1); // the constant
  EXPECT_EQ(key.loc.line, 11);
  EXPECT_EQ(key.loc.col, 4);
}

TEST(FanucSymbols, LookupIsCaseInsensitive) {
  Parsed p = parse(file(kSymbols, "RD key\nWRT Pump\nEND1\nEND2\nEND\n"));
  EXPECT_EQ(p.diags, "");
  ASSERT_GE(p.prog.stmts.size(), 2u);
  EXPECT_EQ(fanuc::formatOperand(p.prog.stmts[0].ops[0]), "X0.1");
  EXPECT_EQ(p.prog.symbols[static_cast<size_t>(p.prog.stmts[1].ops[0].symbol)].name, "PUMP");
}

TEST(FanucSymbols, UnknownSymbol) {
  EXPECT_EQ(diags(file(kSymbols, "RD KEY\nWRT NOPE\nEND1\nEND2\nEND\n")),
            "t.pmc:12:5: error: unknown symbol 'NOPE' [LJ4016]\n");
  // A mnemonic file has a symbol table even without a %@2-E section.
  EXPECT_EQ(diags("%@3\nRD NOPE\nEND1\nEND2\nEND\n%\n"),
            "t.pmc:2:4: error: unknown symbol 'NOPE' [LJ4016]\n");
  // The name of a rejected definition: the use points back at it.
  EXPECT_EQ(
      diags(file("BAD,X999.0\n", "RD BAD\nEND1\nEND2\nEND\n")),
      "t.pmc:2:5: error: symbol 'BAD': address 'X999.0' out of range (X0..X127, "
      "X200..X327) [LJ4006]\n"
      "t.pmc:5:4: error: unknown symbol 'BAD' (its definition on line 2 has an error) [LJ4016]\n");
}

TEST(FanucSymbols, OperandErrorsNameTheSymbol) {
  auto d = [](const std::string &ladder) {
    return diags(file(kSymbols, ladder + "END1\nEND2\nEND\n"));
  };
  EXPECT_EQ(d("RD WORD\n"), "t.pmc:11:4: error: expected a bit address (like R0.0), got byte "
                            "'WORD' (symbol 'WORD' = D100) [LJ4019]\n");
  EXPECT_EQ(d("RD KEY\nMOVB KEY R0\n"),
            "t.pmc:12:6: error: expected a byte address (like D100), got 'KEY' (symbol 'KEY' = "
            "X0.1) [LJ4024]\n");
  EXPECT_EQ(d("RD KEY\nWRT ESP_OK\n"),
            "t.pmc:12:5: error: 'ESP_OK' is read-only (X is written by the machine or the CNC) "
            "(symbol 'ESP_OK' = X0.0) [LJ4001]\n");
  EXPECT_EQ(d("RD KEY\nMOVB R0 MCODE\n"),
            "t.pmc:12:9: error: 'MCODE' is read-only (F is written by the machine or the CNC) "
            "(symbol 'MCODE' = F10) [LJ4001]\n");
  EXPECT_EQ(diags(file("LAST,D9999\n", "RD X0.0\nMOVW LAST R0\nEND1\nEND2\nEND\n")),
            "t.pmc:6:6: error: 'LAST' as 2 bytes runs past the end of D0..D9999 (symbol 'LAST' = "
            "D9999) [LJ4025]\n");
  // A check of the instruction after the operand was read names the symbol as well.
  EXPECT_EQ(diags(file("HEAD,R0\n", "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nDSCH 10 HEAD D0 D2\n"
                                    "END1\nEND2\nEND\n")),
            "t.pmc:8:9: error: table head 'HEAD': DSCH searches the data table only (a D "
            "address, ref 6.7) (symbol 'HEAD' = R0) [LJ4080]\n");
}

TEST(FanucSymbols, LabelsAndSubroutinesAreNotSymbols) {
  const std::string syms = "AT,R0\n";
  EXPECT_EQ(diags(file(syms, "RD X0.0\nJMPB AT\nLBL L1\nEND1\nEND2\nEND\n")),
            "t.pmc:6:6: error: expected a label (L1), got 'AT': labels and subroutines are not "
            "symbols (symbol 'AT' = R0) [LJ4026]\n");
  EXPECT_EQ(diags(file(syms, "END1\nRD X0.0\nCALL DO_IT\nEND2\nSP P1\nSPE\nEND\n")),
            "t.pmc:7:6: error: expected a subroutine (P1), got 'DO_IT': labels and subroutines "
            "are not symbols [LJ4026]\n");
  EXPECT_EQ(diags(file(syms, "END1\nEND2\nSP AT\nSPE\nEND\n")),
            "t.pmc:7:4: error: expected a subroutine (P1), got 'AT': labels and subroutines are "
            "not symbols (symbol 'AT' = R0) [LJ4026]\n");
}

// ---- symbols given with the program (compilePmc's table, e.g. a ladder JSON's) ----

TEST(FanucSymbols, GivenSymbolsAreMergedWithTheFilesOwn) {
  SymbolTable given(fanuc::symbolRules());
  std::string err;
  ASSERT_TRUE(given.add("PUMP", "Y0.0", "COOLANT PUMP", err)) << err;
  // A plain file reads them.
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p = pipeline::compilePmc("RD X0.0\nWRT PUMP\nEND1\nEND2\nEND\n",
                                                          "t.pmc", VerifyOptions{}, d, &given);
  ASSERT_TRUE(p) << d.render();
  ASSERT_EQ(p->symbols.size(), 1u);
  EXPECT_EQ(p->stmts[1].ops[0].symbol, 0);
  // With a file's own symbols after them.
  Parsed m = parse(file("KEY,X0.1\n", "RD KEY\nWRT PUMP\nEND1\nEND2\nEND\n"), &given);
  EXPECT_EQ(m.diags, "");
  ASSERT_EQ(m.prog.symbols.size(), 2u);
  EXPECT_EQ(m.prog.symbols[0].name, "PUMP");
  EXPECT_EQ(m.prog.symbols[1].name, "KEY");
  // A name in both is an error at the file's row.
  EXPECT_EQ(parse(file("pump,Y0.1\n", "RD X0.0\nWRT PUMP\nEND1\nEND2\nEND\n"), &given).diags,
            "t.pmc:2:1: error: duplicate symbol 'pump' (already defined in the symbols given with "
            "the program as 'PUMP'; names are case-insensitive) [LJ4101]\n");
  // Given symbols are checked under the FANUC rules (this one was made under HNC-8's).
  SymbolTable hnc8(hnc8::symbolRules());
  ASSERT_TRUE(hnc8.add("MODE", "W0", "", err)) << err;
  EXPECT_EQ(parse("END1\nEND2\nEND\n", &hnc8).diags,
            "t.pmc:0:0: error: symbols given with the program: symbol 'MODE': unknown address 'W0' "
            "(areas: X Y F G R E A T C K D) [LJ4102]\n");
}

} // namespace
} // namespace lj
