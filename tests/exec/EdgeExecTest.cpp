// Edge contacts (hnc8-core.md 4.8 multi-scan table, 5.3; DIALECT.md 3) and the power-flow
// edge/toggle blocks PLS, PLF, ALT (hnc8-functions-2.md 2.14-2.16 scan tables).
#include "tests/exec/ExecTest.h"

#include <array>

namespace lj::test {
namespace {

class EdgeExec : public ExecTest {};
LJ_EXEC_SUITE(EdgeExec);

// One row of the hnc8-core.md 4.8 table: inputs R1.0 X5.0 R2.0 R4.0, then the expected
// edge columns and R10.1.
struct LdpRow {
  int r10, x50, r20, r40;
  int upR10, downX50, upR20, downR40, out;
};
constexpr std::array<LdpRow, 5> kLdpTable = {{
    {0, 0, 0, 1, 0, 0, 0, 0, 0},
    {1, 0, 1, 0, 1, 0, 1, 1, 1},
    {1, 0, 1, 0, 0, 0, 0, 0, 0},
    {1, 1, 0, 1, 0, 0, 0, 0, 0},
    {1, 0, 1, 0, 0, 1, 1, 1, 1},
}};

void applyRow(Machine &m, const LdpRow &r) {
  m.set("R1.0", r.r10);
  m.set("X5.0", r.x50);
  m.set("R2.0", r.r20);
  m.set("R4.0", r.r40);
}

// hnc8-core.md 4.8: W1 = (up R1.0 or down X5.0) and up R2.0 and down R4.0, per instance; scan 3
// needs ANDP/ANDF to update their memories although ST0 is already 0 (no short-circuit).
TEST_P(EdgeExec, LdpExampleTable) {
  auto m = load("LDP R1.0\nORF X5.0\nANDP R2.0\nANDF R4.0\nOUT R10.1\n");
  ASSERT_TRUE(m);
  for (size_t scan = 0; scan < kLdpTable.size(); ++scan) {
    applyRow(*m, kLdpTable[scan]);
    m->tick();
    EXPECT_EQ(m->get("R10.1"), kLdpTable[scan].out) << "scan " << scan;
  }
}

// The same table, each edge column on its own instance (LDP/LDF push; ORP/ANDF combine).
TEST_P(EdgeExec, LdpExampleColumns) {
  auto m = load(R"(
LDP  R1.0
OUT  R20.0
LDF  X5.0
OUT  R20.1
LDT
ANDP R2.0
OUT  R20.2
LDI  R30.0
ORF  R4.0
OUT  R20.3
)");
  ASSERT_TRUE(m);
  for (size_t scan = 0; scan < kLdpTable.size(); ++scan) {
    const LdpRow &r = kLdpTable[scan];
    applyRow(*m, r);
    m->set("R30.0", 1); // LDI R30.0 pushes 0, so ORF's result is the edge itself
    m->tick();
    SCOPED_TRACE("scan " + std::to_string(scan));
    EXPECT_EQ(m->get("R20.0"), r.upR10);
    EXPECT_EQ(m->get("R20.1"), r.downX50);
    EXPECT_EQ(m->get("R20.2"), r.upR20);
    EXPECT_EQ(m->get("R20.3"), r.downR40);
  }
}

// DIALECT.md 3: each instance owns its memory. Two LDP on the same bit, the second one after a
// coil that writes the bit: the edge appears in the same scan for the later instance.
TEST_P(EdgeExec, EdgeMemoryIsPerInstance) {
  auto m = load("LDP R0.0\nOUT Y0.0\nLD X0.0\nOUT R0.0\nLDP R0.0\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->tick(); // first LDP sees R0.0 = 0, second sees 1 (hnc8-core.md 5.3 consequences)
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 1);
  m->tick(); // the first instance sees the rise one scan later; the second has no new edge
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("Y0.1"), 0);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 0);
}

// LDF/ORP: falling edge pushes, rising edge ORs; a signal already 1 at the first execution is a
// rising edge (hnc8-core.md 5.3 consequences).
TEST_P(EdgeExec, FallingAndOrRising) {
  auto m = load("LDF X0.0\nORP X0.1\nOUT Y0.0\n");
  ASSERT_TRUE(m);
  const int x0[] = {1, 1, 0, 0, 0, 1};
  const int x1[] = {1, 0, 0, 1, 1, 0};
  bool m0 = false, m1 = false; // expected memories, from rise = cur & !m, fall = !cur & m
  for (int scan = 0; scan < 6; ++scan) {
    m->set("X0.0", x0[scan]);
    m->set("X0.1", x1[scan]);
    m->tick();
    bool fall0 = !x0[scan] && m0, rise1 = x1[scan] && !m1;
    m0 = x0[scan];
    m1 = x1[scan];
    EXPECT_EQ(m->get("Y0.0"), fall0 || rise1) << "scan " << scan;
  }
}

// hnc8-functions-2.md 2.15 PLS test scans: R100.0 -> R10.0.
TEST_P(EdgeExec, PlsScanTable) {
  auto m = load("LD R100.0\nPLS 1\nOUT R10.0\n");
  ASSERT_TRUE(m);
  const int in[] = {0, 1, 1, 0, 1}, out[] = {0, 1, 0, 0, 1};
  for (int i = 0; i < 5; ++i) {
    m->set("R100.0", in[i]);
    m->tick();
    EXPECT_EQ(m->get("R10.0"), out[i]) << "scan " << i;
  }
}

// hnc8-functions-2.md 2.16 PLF test scans.
TEST_P(EdgeExec, PlfScanTable) {
  auto m = load("LD R100.0\nPLF 1\nOUT R10.0\n");
  ASSERT_TRUE(m);
  const int in[] = {0, 1, 0, 0}, out[] = {0, 0, 1, 0};
  for (int i = 0; i < 4; ++i) {
    m->set("R100.0", in[i]);
    m->tick();
    EXPECT_EQ(m->get("R10.0"), out[i]) << "scan " << i;
  }
}

// hnc8-functions-2.md 2.14 ALT test sequence (rising edge toggles, state held while EN = 0).
TEST_P(EdgeExec, AltScanTable) {
  auto m = load("LD R100.0\nALT 1\nOUT R10.0\n");
  ASSERT_TRUE(m);
  const int in[] = {0, 1, 1, 0, 1, 0}, out[] = {0, 1, 1, 1, 0, 0};
  for (int i = 0; i < 6; ++i) {
    m->set("R100.0", in[i]);
    m->tick();
    EXPECT_EQ(m->get("R10.0"), out[i]) << "scan " << i;
  }
}

// dialect-notes "Function blocks": one state array per mnemonic, so PLS 3 and PLF 3 do not
// share state; PLS on the left rail (empty ST) has input 1 and fires once (initial prev = 0).
TEST_P(EdgeExec, PulseStatePerMnemonicAndLeftRail) {
  auto m = load("LD X0.0\nPLS 3\nOUT Y0.0\nLD X0.0\nPLF 3\nOUT Y0.1\nLBL L1\nPLS 4\nOUT Y0.2\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("Y0.1"), 0);
  EXPECT_EQ(m->get("Y0.2"), 1);
  m->set("X0.0", 0);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 1); // PLF saw its own prev = 1, untouched by PLS 3
  EXPECT_EQ(m->get("Y0.2"), 0);
}

} // namespace
} // namespace lj::test
