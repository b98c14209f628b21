// Forced contacts (ir/Forces.h, the online monitor's 禁止 / 允许 of hnc8-core.md 6.1
// RESOLUTION (a), docs/serve.md "Forcing"): a forced contact conducts its constant whatever its
// register and NO/NC type; an edge contact still updates its edge memory with the real bit
// (DIALECT.md 3: m = cur on every execution). Forces are keyed by statement id and handed to
// each engine build; the interpreter and the JIT, plus a lock-step state comparison. AOT .so
// files are prebuilt and cannot be forced (the factory refuses, tested below).
#include "tests/exec/ExecTest.h"

#include "engines/EngineSpec.h"
#include "frontends/hnc8/FrontEnd.h"

namespace lj::test {
namespace {

/// The engine `kind` built with `forces` by the engine factory, as serve builds it.
EngineFactory forcedEngine(const std::string &name, const ContactForces &forces) {
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(name);
  EXPECT_TRUE(spec) << name;
  engines::EngineSpec sp = spec ? *spec : engines::EngineSpec{};
  return {name, [sp, forces](const VerifiedProgram &p, std::string &error) {
            engines::EngineOptions o;
            o.forces = forces;
            Result<std::unique_ptr<Engine>> e = engines::makeEngine(sp, p, o);
            if (!e) {
              error = e.status().message();
              return std::unique_ptr<Engine>();
            }
            return std::move(e).value();
          }};
}

/// The forceable engines: the interpreter and the JIT.
std::vector<EngineFactory> forcedEngines(const ContactForces &forces) {
  return {forcedEngine("interp", forces), forcedEngine("jit", forces)};
}

class ForceExec : public ExecTest {
protected:
  /// Verify `text`, force statement `index` to `value`, build this test's engine and run init.
  std::unique_ptr<Machine> loadForced(std::string_view text, int index, int8_t value) {
    std::optional<VerifiedProgram> prog = compileOrFail(text);
    if (!prog) return nullptr;
    EXPECT_LT(static_cast<size_t>(index), prog->stmts.size());
    if (GetParam().name == "aot") return nullptr; // prebuilt: never forced (see AotRefuses)
    ContactForces forces{{prog->stmts[index].id, value}};
    std::unique_ptr<Machine> m = Machine::create(*prog, forcedEngine(GetParam().name, forces));
    if (m) {
      EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    }
    return m;
  }
};
// Forces are compiled in, so only engines built from the program can be forced: the AOT
// factory refuses them (ForceCrossEngine.AotRefusesForces checks that refusal).
std::vector<EngineFactory> forcibleEngines() {
  std::vector<EngineFactory> v;
  for (const EngineFactory &f : registeredEngines())
    if (f.name != "aot") v.push_back(f);
  return v;
}
INSTANTIATE_TEST_SUITE_P(Engines, ForceExec, ::testing::ValuesIn(forcibleEngines()),
                         [](const ::testing::TestParamInfo<EngineFactory> &info) {
                           return info.param.name;
                         });

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
  ContactForces forces;
  for (const Stmt &st : prog->stmts) {
    if (!isContact(st.op)) continue;
    int8_t v = pattern[k++ % std::size(pattern)];
    if (v >= 0) forces[st.id] = v;
  }
  Scenario sc;
  sc.ticks = 64;
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    s.img.X[1] = static_cast<uint8_t>(tick * 37u + (tick >> 2));
    s.img.X[2] = static_cast<uint8_t>(tick * 11u ^ (tick >> 1));
  };
  EXPECT_TRUE(sameStateOnEngines(forcedEngines(forces), *prog, sc));
}

// Forces are keyed by statement id (Stmt::id, DIALECT order), not by position: the contact with
// id 4 here is `AND X1.5` on the second rung. Forced off (禁止), Y1.1 = X1.4 AND 0 = 0 although
// X1.4 = X1.5 = 1, while the first rung, whose AND X1.1 is not forced, follows its inputs; the
// interpreter and the JIT agree on every byte of the state.
TEST(ForceCrossEngine, ForceByStatementIdInterpAndJitAgree) {
  std::optional<VerifiedProgram> prog = compileOrFail("LD X1.0\nAND X1.1\nOUT Y1.0\n"
                                                      "LD X1.4\nAND X1.5\nOUT Y1.1\n"
                                                      "LD X1.4\nOUT Y1.2\n");
  ASSERT_TRUE(prog);
  const Stmt *st = nullptr;
  for (const Stmt &s : prog->stmts)
    if (s.id == 4) st = &s;
  ASSERT_TRUE(st);
  ASSERT_EQ(st->op, Op::And);
  ASSERT_EQ(st->loc.line, 5);
  ContactForces forces{{4, 0}};
  Scenario sc;
  sc.ticks = 8;
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    s.img.X[1] = tick % 2 ? 0x33 : 0x30; // X1.4 = X1.5 = 1 always; X1.0, X1.1 toggle
  };
  auto check = [](int64_t tick, const Machine &ref, uint32_t) {
    if (tick < 0) return;
    EXPECT_EQ(ref.get("Y1.0"), tick % 2) << "tick " << tick;
    EXPECT_EQ(ref.get("Y1.1"), 0) << "tick " << tick << ": AND X1.5 (id 4) is forced off";
    EXPECT_EQ(ref.get("Y1.2"), 1) << "tick " << tick;
  };
  EXPECT_TRUE(sameStateOnEngines(forcedEngines(forces), *prog, sc, check));
}

// A prebuilt .so cannot carry a force: the factory refuses and says why.
TEST(ForceCrossEngine, AotRefusesForces) {
  std::optional<VerifiedProgram> prog = compileOrFail("LD X1.0\nOUT Y1.0\n");
  ASSERT_TRUE(prog);
  engines::EngineOptions o;
  o.forces = {{prog->stmts[0].id, 1}};
  Result<std::unique_ptr<Engine>> e =
      engines::makeEngine({engines::EngineKind::Aot, "unused.so"}, *prog, o);
  ASSERT_FALSE(e);
  EXPECT_NE(e.status().message().find("forcing needs recompilation"), std::string::npos)
      << e.status().message();
}

} // namespace
} // namespace lj::test
