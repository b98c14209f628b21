// FANUC arithmetic and constant instructions (fanuc-c) on every engine: ADDB/SUBB/MULB/DIVB,
// ADD/SUB/MUL/DIV, NUMEB, NUME. The reference describes them only in 6.10 [EXT] (inputs,
// parameters, "R9000 flags set (overflow/sign/zero)", "the DIVB remainder goes to R9002..."),
// with the data formats of 3.1 (signed little-endian binary) and 3.2 (BCD) and the RST/ACT
// conventions of 6.2; expected values are worked out by hand from those texts (cited per test),
// never taken from what the code printed. The readings the reference leaves open are the
// [EXT]/[INF] rows of docs/fanuc-pmc.md ("Arithmetic").
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucArith : public FanucExecTest {
protected:
  /// A byte or a 2-byte word as its unsigned bit pattern.
  static int64_t byte(Machine &m, std::string_view a) { return get(m, a) & 0xFF; }
  static int64_t word(Machine &m, std::string_view a) {
    return get(m, std::string(a) + ":2") & 0xFFFF;
  }
  static constexpr int64_t kZ = 0x01, kN = 0x02, kV = 0x20; // R9000 #0, #1, #5 (ref 2)
};
LJ_EXEC_SUITE(FanucArith);

// 6.10 ADDB with a 2-byte address operand (format 1002, 6.2): 30000 + 5000 = 35000 does not fit
// 2 signed bytes (3.1: -32768..32767), so the result wraps to 35000 - 65536 = -30536, R9000
// gets V (overflow) and N (the stored result is negative), and W1 = 1. With ACT = 0 nothing
// is computed; W1 is held until RST (6.2 "RST clears the error output W1").
TEST_P(FanucArith, AddbOverflowWrapsAndSetsVAndW1) {
  auto m = pmc("RD X0.1\nRD.STK X0.0\nADDB 1002 D0 D2 D4\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 30000);
  set(*m, "D2:2", 5000);
  m->tick(); // ACT = 0
  EXPECT_EQ(get(*m, "D4:2"), 0);
  EXPECT_EQ(byte(*m, "R9000"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), -30536);
  EXPECT_EQ(byte(*m, "R9000"), kV | kN);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.0", 0); // ACT = 0: W1 held, nothing computed
  set(*m, "D0:2", 1);
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), -30536);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.1", 1); // RST = 1 -> W1 = 0
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.1", 0);
  set(*m, "X0.0", 1); // 1 + 5000 = 5001: no flag, no error
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), 5001);
  EXPECT_EQ(byte(*m, "R9000"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.10 ADDB in the `SUB 36` form with a 1-byte constant (format 0001): 100 + 27 = 127 fits;
// 100 + 28 = 128 wraps to -128 (V, N). The R9000 bits other than Z, N, V are kept ([EXT] row,
// as COMPB keeps them, ref 6.6).
TEST_P(FanucArith, AddbConstantOneByteAndOtherFlagsKept) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.1\nSUB 36\n(PRM) 0001\n(PRM) R10\n(PRM) 27\n(PRM) R11\n"
               "WRT R0.0\nRD R9091.0\nRD.STK R9091.1\nADDB 0001 R10 28 R12\nWRT R0.1\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R10", 100);
  set(*m, "R9000", 0xC0);
  m->tick();
  EXPECT_EQ(get(*m, "R11"), 127);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R12"), -128);
  EXPECT_EQ(get(*m, "R0.1"), 1);
  EXPECT_EQ(byte(*m, "R9000"), 0xC0 | kV | kN); // the second ADDB's flags
}

// 6.10 SUBB over 4 bytes: 5 - 5 = 0 sets Z only; -2147483648 - 1 does not fit 4 bytes (3.1)
// and wraps to 2147483647 (V, not N); RST = 1 with ACT = 1 still computes, then clears W1.
TEST_P(FanucArith, SubbZeroAndFourByteOverflow) {
  auto m = pmc("RD X0.1\nRD.STK X0.0\nSUBB 0004 D0 5 D4\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:4", 5);
  set(*m, "D4:4", 77);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "D4:4"), 0);
  EXPECT_EQ(byte(*m, "R9000"), kZ);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "D0:4", -7);
  m->tick();
  EXPECT_EQ(get(*m, "D4:4"), -12);
  EXPECT_EQ(byte(*m, "R9000"), kN);
  set(*m, "D0:4", INT32_MIN + 4);
  m->tick();
  EXPECT_EQ(get(*m, "D4:4"), INT32_MAX);
  EXPECT_EQ(byte(*m, "R9000"), kV);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.1", 1); // RST with ACT: computed, W1 cleared
  set(*m, "D0:4", 10);
  m->tick();
  EXPECT_EQ(get(*m, "D4:4"), 5);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.10 MULB over 2 bytes: 300 * 200 = 60000 wraps to 60000 - 65536 = -5536 (V, N, W1);
// -3 * 7 = -21 (N only).
TEST_P(FanucArith, MulbOverflowAndSign) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.1\nMULB 1002 R100 R102 R104\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R100:2", 300);
  set(*m, "R102:2", 200);
  m->tick();
  EXPECT_EQ(get(*m, "R104:2"), -5536);
  EXPECT_EQ(byte(*m, "R9000"), kV | kN);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R100:2", -3);
  set(*m, "R102:2", 7);
  m->tick();
  EXPECT_EQ(get(*m, "R104:2"), -21);
  EXPECT_EQ(byte(*m, "R9000"), kN);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.10 DIVB: 7 / 2 = 3 with remainder 1 in R9002..R9003 (2 bytes, ref 2 [EXT] R9002-R9005);
// -7 / 2 = -3 remainder -1 (truncation, [EXT] row); a divisor 0 is an error: W1 = 1 and the
// result, the remainder and R9000 are unchanged ([EXT] row).
TEST_P(FanucArith, DivbQuotientRemainderAndDivisionByZero) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.1\nDIVB 1002 D0 D2 D4\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 7);
  set(*m, "D2:2", 2);
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), 3);
  EXPECT_EQ(get(*m, "R9002:2"), 1);
  EXPECT_EQ(byte(*m, "R9000"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "D0:2", -7);
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), -3);
  EXPECT_EQ(get(*m, "R9002:2"), -1);
  EXPECT_EQ(byte(*m, "R9000"), kN);
  set(*m, "D2:2", 0);
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), -3);
  EXPECT_EQ(get(*m, "R9002:2"), -1);
  EXPECT_EQ(byte(*m, "R9000"), kN);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "D2:2", 7); // -7 / 7 = -1, remainder 0
  m->tick();
  EXPECT_EQ(get(*m, "D4:2"), -1);
  EXPECT_EQ(get(*m, "R9002:2"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.10 DIVB over 1 byte with a constant divisor: -128 / -1 = 128 does not fit a byte (3.1), so
// it wraps to -128 (V, N, W1) with remainder 0 in R9002 (1 byte); a constant divisor 0 is
// always the division-by-zero error.
TEST_P(FanucArith, DivbOneByteOverflowAndConstantZero) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.1\nDIVB 0001 R10 -1 R11\nWRT R0.0\n"
               "RD R9091.0\nRD.STK R9091.1\nDIVB 0001 R10 0 R12\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R10", -128);
  set(*m, "R9002", 55);
  set(*m, "R12", 9);
  m->tick();
  EXPECT_EQ(get(*m, "R11"), -128);
  EXPECT_EQ(get(*m, "R9002"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R9000"), kV | kN); // the second DIVB wrote nothing
  EXPECT_EQ(get(*m, "R12"), 9);
  EXPECT_EQ(get(*m, "R0.1"), 1);
}

// 6.10 ADD (BCD, 3.2): BYT = 0 is 2 digits in 1 byte (6.2). 0x45 + 12 = 57 -> 0x57, the second
// byte untouched; 0x99 + 1 = 100 does not fit 2 digits: W1 = 1 and the result is unchanged
// ([EXT] row); with BYT = 1 (4 digits, 2 bytes) 99 + 1 = 100 -> 0x0100. RST clears W1.
TEST_P(FanucArith, AddBcdTwoAndFourDigits) {
  auto m = pmc("RD X0.2\nRD.STK X0.1\nRD.STK X0.0\nADD 0 D0 12 D2\nWRT R0.0\n"
               "RD X0.2\nRD.STK X0.1\nRD.STK X0.0\nADD 0 D4 1 D6\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0", 0x45);
  set(*m, "D3", 0x77);
  set(*m, "D4", 0x99);
  set(*m, "D6:2", 0x1111);
  m->tick(); // ACT = 0
  EXPECT_EQ(byte(*m, "D2"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(byte(*m, "D2"), 0x57);
  EXPECT_EQ(byte(*m, "D3"), 0x77);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(word(*m, "D6"), 0x1111);
  EXPECT_EQ(get(*m, "R0.1"), 1);
  set(*m, "X0.1", 1); // RST
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 0);
  set(*m, "X0.1", 0);
  set(*m, "D1", 0x77);
  set(*m, "X0.2", 1); // BYT = 1: D0..D1 = 0x7745 -> 7745 + 12 = 7757; D4..D5 = 0x0099
  m->tick();
  EXPECT_EQ(word(*m, "D2"), 0x7757);
  EXPECT_EQ(word(*m, "D6"), 0x0100);
  EXPECT_EQ(get(*m, "R0.1"), 0);
}

// 6.10 ADD with an address operand (format 1): a nibble above 9 is not BCD (3.2): W1 = 1 and the
// result is unchanged ([EXT] row "invalid BCD"); 0x0123 + 0x0877 = 1000 -> 0x1000 (BYT = 1).
TEST_P(FanucArith, AddBcdInvalidDigit) {
  auto m = pmc("RD R9091.1\nRD.STK R9091.0\nRD.STK R9091.1\nADD 1 D0 D2 D4\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 0x0123);
  set(*m, "D2:2", 0x0877);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x1000);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "D2:2", 0x001A);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x1000);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "D2:2", 0x0A00);
  set(*m, "D0:2", 0x0001);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x1000);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 6.10 SUB is reachable only as `SUB 20` (the name SUB starts every `SUB n`): 1234 - 234 =
// 1000 -> 0x1000 (BYT = 1); 1234 - 1235 < 0 has no BCD form (3.2: the sign is a separate
// signal): W1 = 1, result unchanged ([EXT] row).
TEST_P(FanucArith, SubBcdAsSub20) {
  auto m = pmc("RD R9091.1\nRD.STK R9091.0\nRD.STK R9091.1\nSUB 20\n(PRM) 1\n(PRM) D0\n"
               "(PRM) D2\n(PRM) D4\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 0x1234);
  set(*m, "D2:2", 0x0234);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x1000);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "D2:2", 0x1235);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x1000);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 6.10 MUL (BCD, BYT = 1): 12 * 34 = 408 -> 0x0408; 100 * 100 = 10000 needs 5 digits: W1 = 1,
// result unchanged.
TEST_P(FanucArith, MulBcdOverflowBeyondFourDigits) {
  auto m = pmc("RD R9091.1\nRD.STK R9091.0\nRD.STK R9091.1\nMUL 1 D0 D2 D4\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 0x0012);
  set(*m, "D2:2", 0x0034);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x0408);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "D0:2", 0x0100);
  set(*m, "D2:2", 0x0100);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x0408);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 6.10 DIV (BCD): 100 / 7 = 14 -> 0x0014 (BYT = 1; the remainder is dropped, [EXT] row); a
// divisor 0 is an error; with BYT = 0 a constant of three digits (150) does not fit the 2 digits
// and is an invalid operand (W1 = 1, [EXT] row).
TEST_P(FanucArith, DivBcdQuotientZeroAndLongConstant) {
  auto m = pmc("RD X0.2\nRD.STK R9091.0\nRD.STK R9091.1\nDIV 1 D0 D2 D4\nWRT R0.0\n"
               "RD X0.2\nRD.STK R9091.0\nRD.STK R9091.1\nDIV 0 D0 150 D6\nWRT R0.1\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 0x0100);
  set(*m, "D2:2", 0x0007);
  set(*m, "X0.2", 1);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x0014);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(word(*m, "D6"), 0x0000); // 100 / 150 = 0
  EXPECT_EQ(get(*m, "R0.1"), 0);
  set(*m, "D2:2", 0);
  m->tick();
  EXPECT_EQ(word(*m, "D4"), 0x0014);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.2", 0); // BYT = 0: D0 = 0x00 -> 0; 150 is too long for 2 digits
  set(*m, "D6:2", 0x4242);
  m->tick();
  EXPECT_EQ(word(*m, "D6"), 0x4242);
  EXPECT_EQ(get(*m, "R0.1"), 1);
}

// 6.10 NUMEB [format 1/2/4 | constant | output]: ACT = 1 writes the binary constant (3.1
// little-endian signed); ACT = 0 writes nothing. No W1: ST0 keeps ACT.
TEST_P(FanucArith, NumebWritesBinaryConstants) {
  auto m = pmc("RD X0.0\nNUMEB 2 -1234 D0\nNUMEB 1 -128 D2\nSUB 40\n(PRM) 4\n(PRM) 2147483647\n"
               "(PRM) D4\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(get(*m, "D0:2"), 0);
  EXPECT_EQ(get(*m, "D4:4"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "D0:2"), -1234);
  EXPECT_EQ(byte(*m, "D2"), 0x80);
  EXPECT_EQ(get(*m, "D4:4"), INT32_MAX);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 6.10 NUME: the BCD constant 1234 is 0x34, 0x12 (3.2 [L411-L427]); BYT = 1 writes both bytes,
// BYT = 0 only the low byte (its last two digits, [INF] row); no W1: ST0 keeps ACT.
TEST_P(FanucArith, NumeWritesBcdConstants) {
  auto m = pmc("RD X0.1\nRD.STK X0.0\nNUME 1234 D0\nWRT R0.0\nRD X0.1\nRD.STK X0.0\nSUB 23\n"
               "(PRM) 63\n(PRM) D2\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D1", 0x55);
  set(*m, "D3", 0x55);
  m->tick(); // ACT = 0
  EXPECT_EQ(byte(*m, "D0"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.0", 1);
  m->tick(); // BYT = 0
  EXPECT_EQ(byte(*m, "D0"), 0x34);
  EXPECT_EQ(byte(*m, "D1"), 0x55);
  EXPECT_EQ(byte(*m, "D2"), 0x63);
  EXPECT_EQ(byte(*m, "D3"), 0x55);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.1", 1); // BYT = 1
  m->tick();
  EXPECT_EQ(word(*m, "D0"), 0x1234);
  EXPECT_EQ(word(*m, "D2"), 0x0063);
}

} // namespace
} // namespace lj::test
