// Symbols as STL operands (docs/plc-dit.md "Symbols"): name syntax, address normalization, and
// the parser resolving names in contacts, coils and blocks exactly like the written address.
#include "frontends/hnc8/Address.h"
#include "frontends/hnc8/FrontEnd.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

SymbolTable table() {
  SymbolTable t(hnc8::symbolRules());
  std::string err;
  EXPECT_TRUE(t.add("START", "X1.0", "", err)) << err;
  EXPECT_TRUE(t.add("Lamp", "Y0.3", "", err)) << err;
  EXPECT_TRUE(t.add("COUNT", "D5", "", err)) << err;
  EXPECT_TRUE(t.add("LIMIT", "W7", "", err)) << err;
  EXPECT_TRUE(t.add("_latch", "R2.1", "", err)) << err;
  EXPECT_TRUE(t.add("主轴", "Y1.0", "", err)) << err;
  EXPECT_TRUE(t.add("DONE", "L3", "", err)) << err;
  EXPECT_TRUE(t.add("HOMING", "S7", "", err)) << err;
  EXPECT_TRUE(t.add("PARTS", "C5.0", "", err)) << err;
  return t;
}

struct Result {
  ParsedProgram prog;
  std::string diags;
};

Result parse(const std::string &text, const SymbolTable *t) {
  Diagnostics d("s.stl");
  Result r{parseStl(text, "s.stl", d, t), d.render()};
  return r;
}

// Every statement of `a` has the operands of `b` (same kinds, areas, numbers, bits, constants).
void expectSameOperands(const ParsedProgram &a, const ParsedProgram &b) {
  ASSERT_EQ(a.stmts.size(), b.stmts.size());
  for (size_t i = 0; i < a.stmts.size(); ++i) {
    EXPECT_EQ(a.stmts[i].op, b.stmts[i].op) << i;
    ASSERT_EQ(a.stmts[i].operandCount, b.stmts[i].operandCount) << i;
    for (int k = 0; k < a.stmts[i].operandCount; ++k)
      EXPECT_EQ(formatOperand(a.stmts[i].ops[k]), formatOperand(b.stmts[i].ops[k]))
          << "statement " << i << " operand " << k;
  }
}

TEST(Symbols, NameSyntax) {
  for (const char *ok : {"A", "_", "ab1", "START_KEY", "XY", "X_1", "X1A", "主轴正转", "é1"})
    EXPECT_TRUE(SymbolTable::isNameShaped(ok)) << ok;
  for (const char *bad : {"", "X10", "L3", "Q7", "d5", "1a", "-a", "a.b", "a-b", "X1.0", "+5"})
    EXPECT_FALSE(SymbolTable::isNameShaped(bad)) << bad;
  SymbolTable t(hnc8::symbolRules());
  std::string err;
  EXPECT_TRUE(t.add(std::string(64, 'a'), "X0.0", "", err)) << err;
  EXPECT_FALSE(t.add(std::string(65, 'b'), "X0.0", "", err));
  EXPECT_NE(err.find("longer than 64 bytes"), std::string::npos) << err;
}

// DIALECT.md 1 ranges; T/C 0..127 and 300..427 with only bit .0; L/S take no bit.
TEST(Symbols, AddressNormalization) {
  std::string err;
  EXPECT_EQ(hnc8::canonicalAddress("x010.3", err), "X10.3");
  EXPECT_EQ(hnc8::canonicalAddress("D0005", err), "D5");
  EXPECT_EQ(hnc8::canonicalAddress("t300.0", err), "T300.0");
  EXPECT_EQ(hnc8::canonicalAddress("S511", err), "S511");
  for (const char *bad : {"", "Q5", "X", "X1.", "X1.0.0", "D5.32", "R0.8", "T5.1", "T200", "L3.1",
                          "S512", "5", "X-1", "X99999999999999999999"})
    EXPECT_EQ(hnc8::canonicalAddress(bad, err), "") << bad;
}

TEST(Symbols, LookupIsCaseInsensitive) {
  SymbolTable t = table();
  ASSERT_NE(t.find("start"), nullptr);
  EXPECT_EQ(t.find("start")->name, "START");
  EXPECT_EQ(t.find("LAMP")->address, "Y0.3");
  EXPECT_EQ(t.find("主轴")->address, "Y1.0");
  EXPECT_EQ(t.find("STOP"), nullptr);
}

TEST(Symbols, ThousandAtMost) {
  SymbolTable t(hnc8::symbolRules());
  std::string err;
  for (int i = 0; i < 1000; ++i) ASSERT_TRUE(t.add("N" + std::to_string(i) + "_", "D0", "", err));
  EXPECT_FALSE(t.add("ONE_MORE", "D0", "", err));
  EXPECT_NE(err.find("too many symbols: at most 1000"), std::string::npos) << err;
}

// Contacts, coils, blocks, jumps and calls: the symbolic program parses to the same operands as
// the program with the addresses written out.
TEST(Symbols, ResolveLikeTheAddress) {
  SymbolTable t = table();
  Result sym = parse("LD START\nANI _latch\nOR start\nOUT Lamp\nSET 主轴\nRST _LATCH\n"
                     "MOV 100 COUNT\nADD COUNT LIMIT COUNT\nCMP COUNT 50\nOUT lamp\n"
                     "JMP DONE\nLBL DONE\nCALL HOMING\nLD PARTS\nOUT Y0.0\n",
                     &t);
  Result addr = parse("LD X1.0\nANI R2.1\nOR X1.0\nOUT Y0.3\nSET Y1.0\nRST R2.1\n"
                      "MOV 100 D5\nADD D5 W7 D5\nCMP D5 50\nOUT Y0.3\n"
                      "JMP L3\nLBL L3\nCALL S7\nLD C5.0\nOUT Y0.0\n",
                      nullptr);
  EXPECT_EQ(sym.diags, "");
  EXPECT_EQ(addr.diags, "");
  expectSameOperands(sym.prog, addr.prog);
}

TEST(Symbols, UnknownSymbolIsLocated) {
  SymbolTable t = table();
  Result r = parse("LD START\nOUT NOPE\nMOV 1 主轴x\n", &t);
  EXPECT_EQ(r.diags, "s.stl:2:5: error: unknown symbol 'NOPE' [LJ3004]\n"
                     "s.stl:3:7: error: unknown symbol '主轴x' [LJ3004]\n");
  EXPECT_EQ(r.prog.stmts.size(), 1u);
}

// The usual operand errors, naming the symbol and its address.
TEST(Symbols, WrongKindNamesTheSymbol) {
  SymbolTable t = table();
  Result r = parse("OUT START\nMOV 1 Lamp\nOUT COUNT\n", &t);
  EXPECT_NE(r.diags.find("s.stl:1:5: error: X1.0 is read-only; OUT cannot write its"),
            std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("(symbol 'START' = X1.0)"), std::string::npos) << r.diags;
  EXPECT_NE(r.diags.find("s.stl:2:7: error: MOV expects a register as"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("got bit address 'Lamp' (symbol 'Lamp' = Y0.3)"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("s.stl:3:5: error: OUT expects a bit address"), std::string::npos)
      << r.diags;
  EXPECT_NE(r.diags.find("got register 'COUNT' (symbol 'COUNT' = D5)"), std::string::npos)
      << r.diags;
  EXPECT_TRUE(r.prog.stmts.empty());
}

// Addresses and constants are never looked up; without a table nothing changes.
TEST(Symbols, AddressesAndConstantsUntouched) {
  SymbolTable t = table();
  Result r = parse("LD X1.0\nMOV -5 D5\nMOV 0x10 W7\n", &t);
  EXPECT_EQ(r.diags, "");
  Result plain = parse("LD START\n", nullptr);
  EXPECT_NE(plain.diags.find("malformed address 'START'"), std::string::npos) << plain.diags;
}

} // namespace
} // namespace lj
