// Located errors of the Neza function blocks and system bits (modicon-neza.md 1.2, 3, 6;
// docs/iec-il.md "Function blocks", "System bits"): unknown blocks, wrong inputs and outputs,
// nesting, instructions the BLK structure does not allow, numbers out of range, writes to
// read-only objects.
#include "tests/iec/IecTest.h"

namespace lj::test {
namespace {

struct Case {
  const char *name, *program, *expected;
};

const Case kCases[] = {
    {"UnknownBlock", "BLK %MW3\nLD %I0.0\nIN\nEND_BLK\n",
     "1:5: error: BLK: '%MW3' is not a function block (%TMi timer, %Ci counter)"},
    {"UnsupportedBlock", "BLK %DR1\nEND_BLK\n", "1:5: error: BLK: '%DR1': the function blocks"},
    {"TimerNumberOutOfRange", "LD %TM32.Q\nST %Q0.0\n",
     "1:4: error: LD: '%TM32.Q': timer number out of range (0..31)"},
    {"CounterNumberOutOfRange", "BLK %C16\nLD %I0.0\nCU\nEND_BLK\n",
     "1:5: error: BLK: '%C16': counter number out of range (0..15)"},
    {"UnknownOutput", "LD %TM0.D\nST %Q0.0\n", "a timer has the outputs Q, V and P"},
    {"WrongInputOfTimer", "BLK %TM0\nLD %I0.0\nCU\nEND_BLK\n",
     "3:1: error: CU is not an input of %TM0 (a timer has the input IN"},
    {"WrongInputOfCounter", "LD %I0.0\nIN %C2\n",
     "2:4: error: IN is not an input of %C2 (a counter has the inputs R, S, CU, CD"},
    {"InputTwice", "BLK %C0\nLD %I0.0\nCU\nLD %I0.1\nCU\nEND_BLK\n",
     "5:1: error: CU of %C0 is given twice in BLK %C0 (line 1)"},
    {"NestedBlocks", "BLK %C0\nLD %I0.0\nCU\nBLK %TM1\nEND_BLK\n",
     "4:1: error: BLK inside BLK %C0 (line 1): blocks do not nest"},
    {"BlockInstructionInsideBlock", "BLK %C0\nLD %I0.0\nCU\nOUT_BLK\nLD D\nIN %TM1\nEND_BLK\n",
     "6:1: error: IN %TM1 inside BLK %C0 (line 1)"},
    {"StoreInInputSection", "BLK %C0\nLD %I0.0\nST %Q0.0\nCU\nEND_BLK\n",
     "3:1: error: ST between BLK and OUT_BLK (BLK %C0 (line 1)): only test instructions"},
    {"MpsInInputSection", "BLK %C0\nLD %I0.0\nMPS\nCU\nEND_BLK\n",
     "3:1: error: MPS between BLK and OUT_BLK"},
    {"JumpInsideBlock", "BLK %C0\nLD %I0.0\nCU\nOUT_BLK\nLD D\nJMPC %L1\nEND_BLK\n%L1 :\n",
     "6:1: error: JMPC inside BLK %C0 (line 1)"},
    {"InputInsideParentheses", "BLK %C0\nLD %I0.0\nAND( %I0.1\nCU\n)\nEND_BLK\n",
     "4:1: error: CU inside parentheses"},
    {"DirectFormInsideParentheses", "LD %I0.0\nOR( %I0.1\nCU %C0\n)\n",
     "3:1: error: CU inside parentheses"},
    {"BareInputOutsideBlock", "LD %I0.0\nCU\n",
     "2:1: error: CU without an operand is a function-block input"},
    {"BareOutputOutsideBlock", "LD D\nST %Q0.0\n",
     "1:4: error: 'D' names a block output only between OUT_BLK and END_BLK"},
    {"BareOutputOfOtherKind", "BLK %TM0\nLD %I0.0\nIN\nOUT_BLK\nLD E\nST %Q0.0\nEND_BLK\n",
     "5:4: error: 'E' is not an output of BLK %TM0 (line 1)"},
    {"BlockNotClosed", "BLK %C0\nLD %I0.0\nCU\n",
     "1:1: error: BLK %C0 (line 1) is not closed by END_BLK before the end of the program"},
    {"EndBlkWithoutBlk", "LD %I0.0\nST %Q0.0\nEND_BLK\n", "3:1: error: END_BLK without BLK"},
    {"TimerWithoutIn", "BLK %TM4\nOUT_BLK\nLD Q\nST %Q0.0\nEND_BLK\n",
     "1:1: error: BLK %TM4 has no IN input before OUT_BLK"},
    {"StoreToTimerOutput", "LD %I0.0\nST %TM0.Q\n",
     "2:4: error: ST %TM0.Q: function-block outputs are read-only"},
    {"WriteCurrentValue", "LD 1\n[%C3.V := 5]\n", "the current value .V is read-only"},
    {"PresetOutOfRange", "LD 1\n[%TM0.P := 10000]\n",
     "2:1: error: :=: preset 10000 out of range (0 <= P <= 9999"},
    {"ConfigPresetOutOfRange", "CONFIG %C1 P=12000\n",
     "1:1: error: CONFIG %C1: preset '12000' out of range (0 <= P <= 9999"},
    {"OneMsTimeBase", "CONFIG %TM2 TB=1MS\n",
     "1:1: error: CONFIG %TM2: the 1 ms time base is only for %TM0 and %TM1"},
    {"UnknownTimeBase", "CONFIG %TM0 TB=5MS\n", "time base '5MS'"},
    {"CounterType", "CONFIG %C0 TON\n", "a counter takes only P=n"},
    {"ConfigTwice", "CONFIG %C0 P=1\nCONFIG %C0 P=2\n",
     "2:1: error: CONFIG %C0 again (first on line 1)"},
    {"ConfigAfterCode", "LD %I0.0\nST %Q0.0\nCONFIG %C0 P=1\n",
     "3:1: error: CONFIG lines come before the first instruction"},
    {"WriteStartBit", "LD %I0.0\nST %S1\n",
     "2:4: error: ST %S1: the runtime writes this system bit before every scan"},
    {"WriteClockBit", "LD %I0.0\nR %S6\n", "2:3: error: R %S6: the runtime writes this system bit"},
};

class IecBlockErrors : public ::testing::TestWithParam<Case> {};

TEST_P(IecBlockErrors, IsLocated) {
  const std::string out = ilErrors(GetParam().program);
  EXPECT_NE(out.find(GetParam().expected), std::string::npos) << out;
}

INSTANTIATE_TEST_SUITE_P(Seed, IecBlockErrors, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case> &i) { return i.param.name; });

// The writable system bits stay writable: only the runtime's table is read-only.
TEST(IecSystemBits, OtherBitsAreWritable) {
  EXPECT_TRUE(compileIlOrFail("LD %I0.0\nST %S2\nS %S40\n"));
}

} // namespace
} // namespace lj::test
