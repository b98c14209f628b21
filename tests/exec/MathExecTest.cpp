// Math blocks: the test values of hnc8-functions-1.md 3.2 plus DIALECT.md 1 width, sign and
// wrap rules and the DIV guards of docs/dialect-notes.md "Function blocks".
#include "tests/exec/ExecTest.h"

#include <climits>

namespace lj::test {
namespace {

class MathExec : public ExecTest {};
LJ_EXEC_SUITE(MathExec);

/// int32 two's-complement wrap of an exact result (DIALECT.md 1).
int32_t wrap32(int64_t v) { return static_cast<int32_t>(static_cast<uint32_t>(v)); }

// hnc8-functions-1.md 3.2 ADD: X3.4=1, D0=5 -> D1=105, R4.0=1; X3.4=0 -> D1 unchanged, R4.0=0.
TEST_P(MathExec, AddExample) {
  auto m = load("LD X3.4\nADD D0 100 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D0", 5);
  m->tick();
  EXPECT_EQ(m->get("D1"), 105);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("X3.4", 0);
  m->set("D0", 7);
  m->tick();
  EXPECT_EQ(m->get("D1"), 105);
  EXPECT_EQ(m->get("R4.0"), 0);
}

// 3.2 SUB: D0=5 -> D1=-95.
TEST_P(MathExec, SubExample) {
  auto m = load("LD X3.4\nSUB D0 100 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D0", 5);
  m->tick();
  EXPECT_EQ(m->get("D1"), -95);
  EXPECT_EQ(m->get("R4.0"), 1);
}

// 3.2 MUL: D1 = D0*100, low 32 bits.
TEST_P(MathExec, MulExampleAndWrap) {
  auto m = load("LD X3.4\nMUL D0 100 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  for (int64_t d0 : {7LL, -3LL, 50000000LL, 2147483647LL, -2147483648LL}) {
    m->set("D0", d0);
    m->tick();
    EXPECT_EQ(m->get("D1"), wrap32(d0 * 100)) << "D0=" << d0;
    EXPECT_EQ(m->get("R4.0"), 1);
  }
}

// 3.2 DIV: D0=250 -> 2; D0=-250 -> -2 (truncation toward zero).
TEST_P(MathExec, DivExample) {
  auto m = load("LD X3.4\nDIV D0 100 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D0", 250);
  m->tick();
  EXPECT_EQ(m->get("D1"), 2);
  m->set("D0", -250);
  m->tick();
  EXPECT_EQ(m->get("D1"), -2);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->state().fault_divzero, 0u);
}

// dialect-notes: DIV by zero writes nothing, outputs 0, counts fault_divzero (EN = 1 only).
TEST_P(MathExec, DivByZero) {
  auto m = load("LD X3.4\nDIV D0 D2 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D0", 250);
  m->set("D1", 77);
  m->set("D2", 0);
  m->tick(); // EN = 0: nothing, no fault
  EXPECT_EQ(m->get("D1"), 77);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_divzero, 0u);
  m->set("X3.4", 1);
  m->tick();
  EXPECT_EQ(m->get("D1"), 77);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_divzero, 1u);
  EXPECT_EQ(m->state().last_fault, uint32_t{LJ_FAULT_NONE}); // harmless: the tick goes on
  m->tick();
  EXPECT_EQ(m->state().fault_divzero, 2u);
  m->set("D2", 5);
  m->tick();
  EXPECT_EQ(m->get("D1"), 50);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->state().fault_divzero, 2u);
}

// DIALECT.md 1 / dialect-notes: INT32_MIN / -1 = INT32_MIN; x / -1 otherwise negates.
TEST_P(MathExec, DivIntMinByMinusOne) {
  auto m = load("LDT\nDIV D0 -1 D1\nOUT R4.0\nLDT\nDIV D2 -1 D3\n");
  ASSERT_TRUE(m);
  m->set("D0", INT32_MIN);
  m->set("D2", -7);
  m->tick();
  EXPECT_EQ(m->get("D1"), INT32_MIN);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->get("D3"), 7);
  EXPECT_EQ(m->state().fault_divzero, 0u);
}

// 3.2 INC: held 3 scans from D0=0 -> 3 (level-triggered); R wraps 255 -> 0, W 32767 -> -32768.
TEST_P(MathExec, IncExampleAndWidthWrap) {
  auto m = load("LD X3.4\nINC D0\nOUT R4.0\nLD X3.4\nINC R1\nLD X3.4\nINC W2\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("R1", 254);
  m->set("W2", 32766);
  m->ticks(3);
  EXPECT_EQ(m->get("D0"), 3);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->get("R1"), 1);      // 254 -> 255 -> 0 -> 1
  EXPECT_EQ(m->get("W2"), -32767); // 32766 -> 32767 -> -32768 -> -32767
  m->set("X3.4", 0);
  m->ticks(2);
  EXPECT_EQ(m->get("D0"), 3);
  EXPECT_EQ(m->get("R4.0"), 0);
}

// 3.2 DEC: D0 = D0 - 1; R=0 becomes 255; D wraps at INT32_MIN.
TEST_P(MathExec, DecExampleAndWrap) {
  auto m = load("LD X3.4\nDEC D0\nOUT R4.0\nLD X3.4\nDEC R1\nLD X3.4\nDEC D5\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D5", INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D0"), -1);
  EXPECT_EQ(m->get("R1"), 255);
  EXPECT_EQ(m->get("D5"), INT32_MAX);
  EXPECT_EQ(m->get("R4.0"), 1);
}

// 3.2 WAND: D0=0xFF -> D1 = 0xFF & 100 = 100. WOR / WXOR: D1 = D0 | 100, D0 ^ 100.
TEST_P(MathExec, BitwiseExamples) {
  auto m = load("LD X3.4\nWAND D0 100 D1\nOUT R4.0\nLD X3.4\nWOR D0 100 D2\nLD X3.4\n"
                "WXOR D0 100 D3\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D0", 0xFF);
  m->tick();
  EXPECT_EQ(m->get("D1"), 100);
  EXPECT_EQ(m->get("D2"), 0xFF | 100);
  EXPECT_EQ(m->get("D3"), 0xFF ^ 100);
  EXPECT_EQ(m->get("R4.0"), 1);
  // Bitwise on the whole int32 operands, not only the low byte.
  m->set("D0", 0x0F0F0F0F);
  m->tick();
  EXPECT_EQ(m->get("D1"), 0x0F0F0F0F & 100);
  EXPECT_EQ(m->get("D2"), 0x0F0F0F0F | 100);
  EXPECT_EQ(m->get("D3"), 0x0F0F0F0F ^ 100);
}

// 3.2 NEG: D0 = -D0; R=5 becomes 251; INT32_MIN stays INT32_MIN; flips every scan.
TEST_P(MathExec, NegExample) {
  auto m = load("LD X3.4\nNEG D0\nOUT R4.0\nLD X3.4\nNEG R1\nLD X3.4\nNEG D2\n");
  ASSERT_TRUE(m);
  m->set("X3.4", 1);
  m->set("D0", 5);
  m->set("R1", 5);
  m->set("D2", INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D0"), -5);
  EXPECT_EQ(m->get("R1"), 251);
  EXPECT_EQ(m->get("D2"), INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D0"), 5);
  EXPECT_EQ(m->get("R1"), 5);
}

// hnc8-functions-1.md 2.2: ADD R0 200 R1 with R0=100 -> R1 = 300 & 0xFF = 44; 16-bit results
// keep the low 16 bits and read back sign-extended.
TEST_P(MathExec, WidthTruncation) {
  auto m = load("LDT\nADD R0 200 R1\nLDT\nADD D0 0 W1\nLDT\nSUB 0 1 Y3\nLDT\nMUL W2 W2 D1\n");
  ASSERT_TRUE(m);
  m->set("R0", 100);
  m->set("D0", 0x12345678);
  m->set("W2", -300);
  m->tick();
  EXPECT_EQ(m->get("R1"), 300 & 0xFF);
  EXPECT_EQ(m->get("W1"), static_cast<int16_t>(0x5678));
  EXPECT_EQ(m->get("Y3"), 255);
  EXPECT_EQ(m->get("D1"), 90000); // W2 read sign-extended: (-300) * (-300)
}

// DIALECT.md 1 read rules: X/Y/R zero-extend, F/G/W sign-extend, D/B/P as is.
TEST_P(MathExec, ReadRulesPerArea) {
  auto m = load("LDT\nADD X1 0 D0\nLDT\nADD R1 0 D1\nLDT\nADD F1 0 D2\nLDT\nADD G1 0 D3\n"
                "LDT\nADD W1 0 D4\nLDT\nADD P1 0 D5\nLDT\nADD B1 0 D6\nLDT\nADD Y1 0 D7\n");
  ASSERT_TRUE(m);
  m->set("X1", 0xF0);
  m->set("R1", 0x80);
  m->set("Y1", 0xFF);
  m->set("F1", -2);
  m->set("G1", -32768);
  m->set("W1", 0xFFFF);
  m->set("P1", -123456);
  m->set("B1", INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D0"), 0xF0);
  EXPECT_EQ(m->get("D1"), 0x80);
  EXPECT_EQ(m->get("D7"), 0xFF);
  EXPECT_EQ(m->get("D2"), -2);
  EXPECT_EQ(m->get("D3"), -32768);
  EXPECT_EQ(m->get("D4"), -1);
  EXPECT_EQ(m->get("D5"), -123456);
  EXPECT_EQ(m->get("D6"), INT32_MIN);
}

// ADD overflow wraps (no UB, DIALECT.md 1).
TEST_P(MathExec, AddSubWrap) {
  auto m = load("LDT\nADD D0 1 D1\nLDT\nSUB D2 1 D3\n");
  ASSERT_TRUE(m);
  m->set("D0", INT32_MAX);
  m->set("D2", INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D1"), INT32_MIN);
  EXPECT_EQ(m->get("D3"), INT32_MAX);
}

// Constants: hex 0xFFFFFFFF is the bit pattern -1 (dialect-notes "Text").
TEST_P(MathExec, HexConstants) {
  auto m = load("LDT\nADD 0xFFFFFFFF 0 D0\nLDT\nADD 0x10 007 D1\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("D0"), -1);
  EXPECT_EQ(m->get("D1"), 23);
}

} // namespace
} // namespace lj::test
