// Incremental compile (JitOptions::incremental, lowering/Incremental.h): every rung group is an
// object of its own, reused from the cache when its key matches. Each test compiles a first
// program into a shared cache, then an edited one, and checks (a) how many groups were
// recompiled and (b) that the edited program still matches the interpreter in full state, which
// fails whenever a group is reused that depends on something the edit changed (a too-coarse key:
// edge slots, jump-target chunks, subroutine numbers, forces).
#include "jit/ObjectCache.h"
#include "tests/jit/JitHarness.h"

#include <memory>
#include <string>

namespace lj::test {
namespace {

jit::JitOptions incremental(std::shared_ptr<jit::ObjectCache> cache, int32_t chunk) {
  jit::JitOptions o;
  o.incremental = true;
  o.cache = std::move(cache);
  o.chunkStatements = chunk;
  o.compileThreads = 2;
  return o;
}

/// Compile `prog` with `o` and return its times (the engine is dropped).
jit::CompileTimes compileTimes(const VerifiedProgram &prog, const jit::JitOptions &o) {
  std::string error;
  jit::CompileTimes t;
  std::unique_ptr<Engine> e = jit::compile(prog, o, error, &t);
  EXPECT_TRUE(e) << error;
  return t;
}

/// Scenario toggling X0..X3 bit by bit so that edge contacts and their memories matter.
Scenario toggling(uint32_t ticks) {
  Scenario sc;
  sc.ticks = ticks;
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    for (int k = 0; k < 4; ++k)
      s.img.X[k] = static_cast<uint8_t>((tick * 37u + static_cast<uint32_t>(k) * 11u) >> 1);
  };
  return sc;
}

// Rungs of the form "LDP Xa.b / OUT Yc.d": each holds an edge slot numbered in program order.
std::string edgeRungs(int first, int count) {
  std::string s;
  for (int i = first; i < first + count; ++i)
    s += "LDP X" + std::to_string(i % 4) + "." + std::to_string(i % 8) + "\nOUT Y" +
         std::to_string(i / 8) + "." + std::to_string(i % 8) + "\n";
  return s;
}

TEST(IncrementalJit, RandomProgramsMatchInterpreter) {
  for (uint64_t seed : {201u, 202u, 203u, 204u, 205u, 206u}) {
    std::string text;
    auto prog = randomProgramOrFail(seed, 800, &text);
    ASSERT_TRUE(prog) << text;
    Scenario sc = randomScenario(seed, 25, static_cast<uint32_t>(1 + seed % 13), 3000);
    for (int32_t chunk : {8, 150}) {
      jit::JitOptions o = incremental(std::make_shared<jit::ObjectCache>(""), chunk);
      o.tier = seed % 2 ? jit::Tier::Fast : jit::Tier::Optimizing;
      ::testing::AssertionResult same = jitMatchesInterpreter(*prog, o, sc);
      ASSERT_TRUE(same) << "seed " << seed << " chunk " << chunk << "\n" << text;
    }
  }
}

TEST(IncrementalJit, OneRungEditRecompilesOneGroup) {
  auto cache = std::make_shared<jit::ObjectCache>("");
  const jit::JitOptions o = incremental(cache, 4);
  // 40 rungs that keep their edge slots: change one output address in the middle.
  std::string a = edgeRungs(0, 40) + "1END\n2END\n";
  std::string b = a;
  b.replace(b.find("OUT Y2.4"), 8, "OUT Y9.4");
  auto pa = compileOrFail(a), pb = compileOrFail(b);
  ASSERT_TRUE(pa && pb);
  jit::CompileTimes ta = compileTimes(*pa, o);
  EXPECT_GT(ta.leaves, 10u);
  EXPECT_EQ(ta.leavesCompiled, ta.leaves);
  jit::CompileTimes tb = compileTimes(*pb, o);
  EXPECT_EQ(tb.leaves, ta.leaves);
  EXPECT_EQ(tb.leavesCompiled, 1u);
  EXPECT_TRUE(jitMatchesInterpreter(*pb, o, toggling(40)));
  // The unchanged program again: everything from the cache.
  EXPECT_EQ(compileTimes(*pa, o).leavesCompiled, 0u);
}

TEST(IncrementalJit, EdgeSlotsShiftedByAnInsertRecompileTheGroupsAfterIt) {
  // Inserting an edge contact in the first rung renumbers the edge slot of every later edge
  // contact: their statements are unchanged but their code is not. A key without the slots
  // would reuse the first program's groups, whose contacts then share the wrong edge memories.
  auto cache = std::make_shared<jit::ObjectCache>("");
  const jit::JitOptions o = incremental(cache, 4);
  std::string a = "LD X3.7\nOUT Y30.0\n" + edgeRungs(0, 30) + "1END\n2END\n";
  std::string b = "LDP X3.7\nOUT Y30.0\n" + edgeRungs(0, 30) + "1END\n2END\n";
  auto pa = compileOrFail(a), pb = compileOrFail(b);
  ASSERT_TRUE(pa && pb);
  jit::CompileTimes ta = compileTimes(*pa, o);
  jit::CompileTimes tb = compileTimes(*pb, o);
  // Every group holding a shifted edge slot is new; only the empty init / PLC2 bodies are not.
  EXPECT_GE(tb.leavesCompiled + 2, tb.leaves);
  EXPECT_TRUE(jitMatchesInterpreter(*pb, o, toggling(40)));
  // Rungs without slots after the insert keep their keys.
  std::string c = "LD X3.7\nOUT Y30.0\n" + edgeRungs(0, 2);
  std::string d = "LDP X3.7\nOUT Y30.0\n" + edgeRungs(0, 2);
  for (int i = 0; i < 20; ++i) {
    c += "LD X2." + std::to_string(i % 8) + "\nOUT R" + std::to_string(i) + ".1\n";
    d += "LD X2." + std::to_string(i % 8) + "\nOUT R" + std::to_string(i) + ".1\n";
  }
  auto pc = compileOrFail(c + "1END\n2END\n"), pd = compileOrFail(d + "1END\n2END\n");
  ASSERT_TRUE(pc && pd);
  jit::CompileTimes tc = compileTimes(*pc, o);
  jit::CompileTimes td = compileTimes(*pd, o);
  EXPECT_LT(td.leavesCompiled, tc.leaves / 2) << "rungs without slots are reused";
  EXPECT_GT(ta.leaves, 0u);
  EXPECT_TRUE(jitMatchesInterpreter(*pd, o, toggling(40)));
}

TEST(IncrementalJit, JumpsAcrossGroupsFollowTheChunkTheyLandIn) {
  // A JMP over many rungs is cut inside its span: the jumping chunk returns the index of the
  // chunk that starts with the label. Inserting rungs between them moves the label to another
  // chunk while the jumping chunk's statements stay the same.
  auto cache = std::make_shared<jit::ObjectCache>("");
  const jit::JitOptions o = incremental(cache, 4);
  auto body = [](int between) {
    std::string s = "LD X0.0\nJMP L7\n";
    for (int i = 0; i < between; ++i)
      s += "LD X1." + std::to_string(i % 8) + "\nOUT R" + std::to_string(i) + ".2\n";
    return s + "LBL L7\nLD X2.0\nOUT Y1.1\n1END\n2END\n";
  };
  auto pa = compileOrFail(body(30)), pb = compileOrFail(body(38));
  ASSERT_TRUE(pa && pb);
  compileTimes(*pa, o);
  compileTimes(*pb, o);
  Scenario sc = toggling(30);
  EXPECT_TRUE(jitMatchesInterpreter(*pb, o, sc));
  EXPECT_TRUE(jitMatchesInterpreter(*pa, o, sc));
}

TEST(IncrementalJit, CallsNameTheSubroutineByNumber) {
  // A subroutine inserted before S2 shifts S2's index in VerifiedProgram::subs; the calling
  // group must still call S2 (its key holds the number, and the symbol is lj_sub<number>).
  auto cache = std::make_shared<jit::ObjectCache>("");
  const jit::JitOptions o = incremental(cache, 4);
  const std::string main = "LD X0.1\nCALL S2\nOUT Y0.0\nLD X0.2\nCALL S3\nOUT Y0.1\n1END\n2END\n";
  const std::string s2 = "SP S2\nLDT\nINC D2\nSPE\n", s3 = "SP S3\nLDT\nINC D3\nSPE\n";
  auto pa = compileOrFail(main + s2 + s3);
  auto pb = compileOrFail(main + "SP S1\nLDT\nINC D1\nSPE\n" + s2 + s3);
  auto pc = compileOrFail(main + s3 + s2); // same subroutines, other order
  ASSERT_TRUE(pa && pb && pc);
  compileTimes(*pa, o);
  jit::CompileTimes tb = compileTimes(*pb, o);
  EXPECT_LT(tb.leavesCompiled, tb.leaves);
  Scenario sc;
  sc.ticks = 6;
  sc.hostInputs = [](uint32_t tick, lj_state &s) { s.img.X[0] = static_cast<uint8_t>(tick * 3); };
  EXPECT_TRUE(jitMatchesInterpreter(*pb, o, sc));
  compileTimes(*pc, o);
  EXPECT_TRUE(jitMatchesInterpreter(*pc, o, sc));
}

TEST(IncrementalJit, ForcesRecompileOnlyTheForcedGroup) {
  auto cache = std::make_shared<jit::ObjectCache>("");
  jit::JitOptions o = incremental(cache, 4);
  auto p =
      compileOrFail(edgeRungs(0, 12) + "LD X2.2\nOUT Y7.7\n" + edgeRungs(12, 12) + "1END\n2END\n");
  ASSERT_TRUE(p);
  jit::CompileTimes t0 = compileTimes(*p, o);
  StmtId forcedId{};
  for (const Stmt &s : p->stmts)
    if (s.op == Op::Load && s.loc.line == 25) // LD X2.2, after 12 two-line rungs
      forcedId = s.id;
  o.forces[forcedId] = 1;
  jit::CompileTimes t1 = compileTimes(*p, o);
  EXPECT_EQ(t1.leaves, t0.leaves);
  EXPECT_EQ(t1.leavesCompiled, 1u);
  // The forced build conducts the constant (允许: 1): Y7.7 = 1 while X2.2 = 0.
  std::unique_ptr<Machine> m = Machine::create(*p, jitEngine(o));
  ASSERT_TRUE(m);
  m->init();
  m->set("X2.2", 0);
  m->tick();
  EXPECT_EQ(m->get("Y7.7"), 1);
  // Unforced again: the first build's groups, all from the cache, and Y7.7 follows X2.2.
  o.forces.clear();
  EXPECT_EQ(compileTimes(*p, o).leavesCompiled, 0u);
  std::unique_ptr<Machine> u = Machine::create(*p, jitEngine(o));
  ASSERT_TRUE(u);
  u->init();
  u->set("X2.2", 0);
  u->tick();
  EXPECT_EQ(u->get("Y7.7"), 0);
}

} // namespace
} // namespace lj::test
