// Forced contacts (Stmt::force, the online monitor's 禁止 / 允许 of hnc8-core.md 6.1
// RESOLUTION (a), docs/serve.md "Forcing"): a forced contact conducts its constant whatever its
// register and NO/NC type; an edge contact still updates its edge memory with the real bit
// (DIALECT.md 3: m = cur on every execution). Every engine, plus a lock-step state comparison.
#include "tests/exec/ExecTest.h"

#include "frontends/hnc8/FrontEnd.h"

namespace lj::test {
namespace {

class ForceExec : public ExecTest {
protected:
  /// Verify `text`, force statement `index` to `value`, build this test's engine and run init.
  std::unique_ptr<Machine> loadForced(std::string_view text, int index, int8_t value) {
    std::optional<VerifiedProgram> prog = compileOrFail(text);
    if (!prog) return nullptr;
    EXPECT_LT(static_cast<size_t>(index), prog->stmts.size());
    prog->stmts[index].force = value;
    std::unique_ptr<Machine> m = Machine::create(*prog, GetParam());
    if (m) {
      EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    }
    return m;
  }
};
LJ_EXEC_SUITE(ForceExec);

// One contact of each plain kind, placed so the rung result equals the contact's conducting
// value: LD/LDI alone, AND/ANI after LDT (1 AND c = c), OR/ORI after a 0 (0 OR c = c).
struct PlainCase {
  const char *text;
  int contact; ///< statement index of the forced contact
};
const PlainCase kPlain[] = {
    {"LD X1.0\nOUT Y1.0\n", 0},          {"LDI X1.0\nOUT Y1.0\n", 0},
    {"LDT\nAND X1.0\nOUT Y1.0\n", 1},    {"LDT\nANI X1.0\nOUT Y1.0\n", 1},
    {"LD R0.0\nOR X1.0\nOUT Y1.0\n", 1}, {"LD R0.0\nORI X1.0\nOUT Y1.0\n", 1},
};

TEST_P(ForceExec, PlainContactsConductTheirConstant) {
  for (const PlainCase &c : kPlain) {
    for (int8_t force : {0, 1}) {
      SCOPED_TRACE(std::string(c.text) + " forced " + std::to_string(force));
      auto m = loadForced(c.text, c.contact, force);
      ASSERT_TRUE(m);
      for (int x : {0, 1, 0, 1}) { // NO/NC and the register value are ignored
        m->set("X1.0", x);
        EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
        EXPECT_EQ(m->get("Y1.0"), force);
      }
    }
  }
}

// A forced contact is still combined with ST0: 0 AND 1 = 0, 1 OR 0 = 1.
TEST_P(ForceExec, ForcedContactStillCombines) {
  auto andOn = loadForced("LD R0.0\nAND X1.0\nOUT Y1.0\n", 1, 1);
  ASSERT_TRUE(andOn);
  andOn->set("X1.0", 1);
  andOn->tick();
  EXPECT_EQ(andOn->get("Y1.0"), 0);
  auto orOff = loadForced("LDT\nOR X1.0\nOUT Y1.0\n", 1, 0);
  ASSERT_TRUE(orOff);
  orOff->tick();
  EXPECT_EQ(orOff->get("Y1.0"), 1);
}

// Edge contacts: the forced value replaces the edge result, and the edge memory keeps
// following the real bit, so the first real edge after a restore is judged correctly.
TEST_P(ForceExec, EdgeContactsKeepTheirMemory) {
  const PlainCase cases[] = {
      {"LDP X1.0\nOUT Y1.0\n", 0},          {"LDF X1.0\nOUT Y1.0\n", 0},
      {"LDT\nANDP X1.0\nOUT Y1.0\n", 1},    {"LDT\nANDF X1.0\nOUT Y1.0\n", 1},
      {"LD R0.0\nORP X1.0\nOUT Y1.0\n", 1}, {"LD R0.0\nORF X1.0\nOUT Y1.0\n", 1}};
  for (const PlainCase &c : cases) {
    for (int8_t force : {0, 1}) {
      SCOPED_TRACE(std::string(c.text) + " forced " + std::to_string(force));
      auto m = loadForced(c.text, c.contact, force);
      ASSERT_TRUE(m);
      int slot = m->program().info[c.contact].slot;
      ASSERT_GE(slot, 0);
      for (int x : {0, 1, 1, 0, 1}) {
        m->set("X1.0", x);
        m->tick();
        EXPECT_EQ(m->get("Y1.0"), force);
        EXPECT_EQ(m->state().edge[slot], x) << "edge memory must follow the real bit";
      }
    }
  }
}

// Lock-step comparison of the complete state on every engine: a program with every contact
// kind, some forced on, some off, some not forced, under a changing input pattern.
TEST(ForceCrossEngine, ForcedProgramSameStateOnAllEngines) {
  std::optional<VerifiedProgram> prog = compileOrFail(R"(
LD X1.0
AND X1.1
ORI X1.2
OUT Y1.0
LDI X1.3
ANDP X1.4
ORF X1.5
OUT Y1.1
LDP X1.6
ANI X1.7
OR X2.0
ANDF X2.1
OUT Y1.2
LDF X2.2
ORP X2.3
OUT Y1.3
)");
  ASSERT_TRUE(prog);
  const int8_t pattern[] = {1, -1, 0, 1, 0, -1, 1, 0, -1, 1, 1, 0, 0, 1, -1};
  size_t k = 0;
  for (Stmt &st : prog->stmts)
    if (isContact(st.op)) st.force = pattern[k++ % std::size(pattern)];
  Scenario sc;
  sc.ticks = 64;
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    s.img.X[1] = static_cast<uint8_t>(tick * 37u + (tick >> 2));
    s.img.X[2] = static_cast<uint8_t>(tick * 11u ^ (tick >> 1));
  };
  EXPECT_TRUE(sameStateOnAllEngines(*prog, sc));
}

} // namespace
} // namespace lj::test
