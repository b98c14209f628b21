// Data operations, moves: XMOV XCH BMOV FMOV ZRST on every engine, with the test values of
// hnc8-functions-2.md 2.2-2.6 and the rules of DIALECT.md 4 / docs/dialect-notes.md "Data
// operations" (index faults, memmove, fill and bit-range details). Tables, packing, ACVT and
// PTN/NTP are in DataTableInstrTest.cpp.
#include "tests/exec/ExecTest.h"

#include <string>

namespace lj::test {
namespace {

class DataMoveExec : public ExecTest {};
LJ_EXEC_SUITE(DataMoveExec);

// functions-2 2.2 example: D1=3, D2=7, B3=1234, B7=0 -> B7=1234, B3 unchanged; ST0 := EN.
TEST_P(DataMoveExec, XmovBToB) {
  auto m = load("LDT\nXMOV 1 D1 1 D2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D1", 3);
  m->set("D2", 7);
  m->set("B3", 1234);
  m->tick();
  EXPECT_EQ(m->get("B7"), 1234);
  EXPECT_EQ(m->get("B3"), 1234);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->state().fault_index, 0u);
}

// functions-2 2.2: `XMOV 0 R10 0 D5` is MOV R10 D5 (R zero-extends); `XMOV 2 R1 0 D0` with
// R1=30, P30=77 gives D0=77.
TEST_P(DataMoveExec, XmovFormatsZeroAndTwo) {
  auto m = load("LDT\nXMOV 0 R10 0 D5\nLDT\nXMOV 2 R1 0 D0\n");
  ASSERT_TRUE(m);
  m->set("R10", 200);
  m->set("R1", 30);
  m->set("P30", 77);
  m->tick();
  EXPECT_EQ(m->get("D5"), 200);
  EXPECT_EQ(m->get("D0"), 77);
}

// functions-2 2.2 + DIALECT.md 4: D1=60 is out of range for B -> no change, output 0,
// fault_index counts once per execution; a negative index is out of range too.
TEST_P(DataMoveExec, XmovIndexOutOfRange) {
  auto m = load("LDT\nXMOV 1 D1 1 D2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D1", 60);
  m->set("D2", 7);
  m->set("B7", 5);
  m->tick();
  EXPECT_EQ(m->get("B7"), 5);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_index, 1u);
  m->set("D1", 3);
  m->set("D2", -1); // destination index out of range: nothing written either
  m->set("B3", 9);
  m->tick();
  EXPECT_EQ(m->get("B7"), 5);
  EXPECT_EQ(m->get("B0"), 0);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_index, 2u);
  m->set("D2", 49); // last B element: in range
  m->tick();
  EXPECT_EQ(m->get("B49"), 9);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->state().fault_index, 2u);
}

// functions-2 resolution 18: P is written only through format 2 (here as the destination);
// with an empty ST the output is pushed (dialect-notes "Stacks and blocks").
TEST_P(DataMoveExec, XmovWritesPThroughFormatTwo) {
  auto m = load("XMOV 0 D0 2 R1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("R1", 5);
  m->set("D0", 99);
  m->tick();
  EXPECT_EQ(m->get("P5"), 99);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("R1", 200); // P0..P199: out of range
  m->set("D0", 1);
  m->tick();
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_index, 1u);
}

// functions-2 0.4: EN = 0 does nothing (no fault check either); the output is EN.
TEST_P(DataMoveExec, XmovDisabled) {
  auto m = load("LD X1.0\nXMOV 1 D1 0 W3\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D1", 2);
  m->set("B2", -7);
  m->tick();
  EXPECT_EQ(m->get("W3"), 0);
  EXPECT_EQ(m->get("R4.0"), 0);
  m->set("D1", 99);
  m->tick();
  EXPECT_EQ(m->state().fault_index, 0u);
  m->set("D1", 2);
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("W3"), -7); // B2 -> W3, truncated to 16 bits
  EXPECT_EQ(m->get("R4.0"), 1);
}

// functions-2 2.5 example: D1=3, D2=7, B3=10, B7=20 -> B3=20, B7=10.
TEST_P(DataMoveExec, XchBAndB) {
  auto m = load("LDT\nXCH 1 D1 1 D2\n");
  ASSERT_TRUE(m);
  m->set("D1", 3);
  m->set("D2", 7);
  m->set("B3", 10);
  m->set("B7", 20);
  m->tick();
  EXPECT_EQ(m->get("B3"), 20);
  EXPECT_EQ(m->get("B7"), 10);
}

// functions-2 2.5 mixed widths: XCH 0 R1 0 D1 with R1=5, D1=300 -> R1=44, D1=5; the same
// register on both sides changes nothing.
TEST_P(DataMoveExec, XchWidthsAndSameRegister) {
  auto m = load("LDT\nXCH 0 R1 0 D1\nLDT\nXCH 1 W0 0 B4\n");
  ASSERT_TRUE(m);
  m->set("R1", 5);
  m->set("D1", 300);
  m->set("W0", 4);
  m->set("B4", 123);
  m->tick();
  EXPECT_EQ(m->get("R1"), 44);
  EXPECT_EQ(m->get("D1"), 5);
  EXPECT_EQ(m->get("B4"), 123);
}

// dialect-notes "Data operations": both operands are resolved before anything is written, so
// `XCH 0 D0 1 D0` with D0=3 exchanges D0 and B3 even though D0 changes.
TEST_P(DataMoveExec, XchResolvesBeforeWriting) {
  auto m = load("LDT\nXCH 0 D0 1 D0\n");
  ASSERT_TRUE(m);
  m->set("D0", 3);
  m->set("B3", 77);
  m->tick();
  EXPECT_EQ(m->get("D0"), 77);
  EXPECT_EQ(m->get("B3"), 3);
  EXPECT_EQ(m->state().fault_index, 0u);
}

// DIALECT.md 4 for a block without an output (dialect-notes): out of range -> nothing written,
// fault_index + 1 and ST0 := 0; in range -> ST0 unchanged. Format 2 exchanges P values.
TEST_P(DataMoveExec, XchFaultAndP) {
  auto m = load("LDT\nXCH 2 R1 2 R2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("R1", 10);
  m->set("R2", 11);
  m->set("P10", -1);
  m->set("P11", 65536);
  m->tick();
  EXPECT_EQ(m->get("P10"), 65536);
  EXPECT_EQ(m->get("P11"), -1);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("R2", 250); // R zero-extends: 250 > 199
  m->tick();
  EXPECT_EQ(m->get("P10"), 65536);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_index, 1u);
}

// functions-2 2.3 example: D0=11, D1=22 -> D2=11, D3=22; overlap test: BMOV D0 D1 3 with
// D0..D3 = 1,2,3,4 gives D1..D3 = 1,2,3 (memmove semantics).
TEST_P(DataMoveExec, BmovExampleAndOverlap) {
  auto m = load("LDT\nBMOV D0 D2 2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D0", 11);
  m->set("D1", 22);
  m->tick();
  EXPECT_EQ(m->get("D2"), 11);
  EXPECT_EQ(m->get("D3"), 22);
  EXPECT_EQ(m->get("R4.0"), 1);

  auto o = load("LDT\nBMOV D0 D1 3\n");
  ASSERT_TRUE(o);
  for (int k = 0; k < 4; ++k) o->set("D" + std::to_string(k), k + 1);
  o->tick();
  EXPECT_EQ(o->get("D0"), 1);
  EXPECT_EQ(o->get("D1"), 1);
  EXPECT_EQ(o->get("D2"), 2);
  EXPECT_EQ(o->get("D3"), 3);
}

// functions-2 2.3: element-wise with the read rule of the source and the write truncation of
// the destination; EN = 0 does nothing.
TEST_P(DataMoveExec, BmovMixedWidths) {
  auto m = load("LD X1.0\nBMOV W0 R0 2\nLD X1.0\nBMOV X5 D10 2\n");
  ASSERT_TRUE(m);
  m->set("W0", 300);
  m->set("W1", -1);
  m->set("X5", 200);
  m->set("X6", 7);
  m->tick();
  EXPECT_EQ(m->get("R0"), 0);
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("R0"), 44);
  EXPECT_EQ(m->get("R1"), 255);
  EXPECT_EQ(m->get("D10"), 200); // X zero-extends
  EXPECT_EQ(m->get("D11"), 7);
}

// functions-2 2.3 memmove semantics on ranges longer than the unrolled ones, both directions.
TEST_P(DataMoveExec, BmovLongOverlaps) {
  auto m = load("LD X1.0\nBMOV W0 W10 60\nLD X1.1\nBMOV G10 G0 60\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 70; ++k) {
    m->set("W" + std::to_string(k), k + 1);
    m->set("G" + std::to_string(k), 1000 + k);
  }
  m->set("X1.0", 1);
  m->set("X1.1", 1);
  m->tick();
  for (int k = 0; k < 10; ++k) EXPECT_EQ(m->get("W" + std::to_string(k)), k + 1) << k;
  for (int k = 0; k < 60; ++k) EXPECT_EQ(m->get("W" + std::to_string(10 + k)), k + 1) << k;
  for (int k = 0; k < 60; ++k) EXPECT_EQ(m->get("G" + std::to_string(k)), 1010 + k) << k;
  for (int k = 60; k < 70; ++k) EXPECT_EQ(m->get("G" + std::to_string(k)), 1000 + k) << k;
}

// functions-2 2.4 example: D3=9 -> D0=D1=D2=9; the source inside the range is read once;
// FMOV has no output (ST0 stays EN).
TEST_P(DataMoveExec, FmovExampleAndSourceInRange) {
  auto m = load("LD X1.0\nFMOV D0 D2 D3\nOUT R4.0\nLDT\nFMOV D10 D13 D11\n");
  ASSERT_TRUE(m);
  m->set("D3", 9);
  m->set("D11", 5);
  m->tick();
  EXPECT_EQ(m->get("D0"), 0);
  EXPECT_EQ(m->get("R4.0"), 0);
  for (int k = 10; k <= 13; ++k) EXPECT_EQ(m->get("D" + std::to_string(k)), 5) << k;
  m->set("X1.0", 1);
  m->tick();
  for (int k = 0; k <= 2; ++k) EXPECT_EQ(m->get("D" + std::to_string(k)), 9) << k;
  EXPECT_EQ(m->get("R4.0"), 1);
}

// functions-2 2.4 on a long range (truncated to the destination width), EN gating it.
TEST_P(DataMoveExec, FmovLongRange) {
  auto m = load("LD X1.0\nFMOV G100 G199 -2\nLD X1.0\nFMOV Y0 Y40 W0\n");
  ASSERT_TRUE(m);
  m->set("W0", 0x1234);
  m->tick();
  EXPECT_EQ(m->get("G150"), 0);
  m->set("X1.0", 1);
  m->tick();
  for (int k = 100; k <= 199; ++k) EXPECT_EQ(m->get("G" + std::to_string(k)), -2) << k;
  EXPECT_EQ(m->get("G99"), 0);
  EXPECT_EQ(m->get("G200"), 0);
  for (int k = 0; k <= 40; ++k) EXPECT_EQ(m->get("Y" + std::to_string(k)), 0x34) << k;
  EXPECT_EQ(m->get("Y41"), 0);
}

// functions-2 2.6 example: D0=5, D1=6, D2=7 -> D0=0, D1=0, D2=7; output EN.
TEST_P(DataMoveExec, ZrstWords) {
  auto m = load("LDT\nZRST D0 D1\nOUT R4.0\nLD X1.0\nZRST W0 W99\n");
  ASSERT_TRUE(m);
  m->set("D0", 5);
  m->set("D1", 6);
  m->set("D2", 7);
  for (int k = 0; k <= 100; ++k) m->set("W" + std::to_string(k), -k - 1);
  m->tick();
  EXPECT_EQ(m->get("D0"), 0);
  EXPECT_EQ(m->get("D1"), 0);
  EXPECT_EQ(m->get("D2"), 7);
  EXPECT_EQ(m->get("R4.0"), 1);
  EXPECT_EQ(m->get("W50"), -51); // X1.0 = 0: nothing
  m->set("X1.0", 1);
  m->tick();
  for (int k = 0; k <= 99; ++k) EXPECT_EQ(m->get("W" + std::to_string(k)), 0) << k;
  EXPECT_EQ(m->get("W100"), -101);
}

// functions-2 2.6 bit form: ZRST R10.0 R11.3 clears R10.0-R10.7 and R11.0-R11.3; inside one
// element; and a long range (index * width + bit order).
TEST_P(DataMoveExec, ZrstBits) {
  auto m = load("LDT\nZRST R10.0 R11.3\nLDT\nZRST W3.4 W3.7\nLDT\nZRST R100.4 R150.2\n");
  ASSERT_TRUE(m);
  for (int k = 9; k <= 12; ++k) m->set("R" + std::to_string(k), 0xFF);
  m->set("W3", -1);
  for (int k = 99; k <= 151; ++k) m->set("R" + std::to_string(k), 0xFF);
  m->tick();
  EXPECT_EQ(m->get("R9"), 0xFF);
  EXPECT_EQ(m->get("R10"), 0);
  EXPECT_EQ(m->get("R11"), 0xF0);
  EXPECT_EQ(m->get("R12"), 0xFF);
  EXPECT_EQ(m->get("W3"), static_cast<int16_t>(0xFF0F));
  EXPECT_EQ(m->get("R99"), 0xFF);
  EXPECT_EQ(m->get("R100"), 0x0F);
  for (int k = 101; k <= 149; ++k) EXPECT_EQ(m->get("R" + std::to_string(k)), 0) << k;
  EXPECT_EQ(m->get("R150"), 0xF8);
  EXPECT_EQ(m->get("R151"), 0xFF);
}

} // namespace
} // namespace lj::test
