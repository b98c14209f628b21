// Every real project under ../shared/realprograms/classicladder reads (LinuxCNC .clp files and
// the upstream .clp/.clprj ones), with the facts ../shared/reference/classicladder.md section 6
// counts; built only when that folder exists (a clone has none).
#include "frontends/classicladder/Reader.h"

#include <filesystem>
#include <gtest/gtest.h>

using namespace lj::classicladder;
namespace fs = std::filesystem;

namespace {

std::string real(const std::string &rel) { return std::string(LJ_CL_REAL_DIR) + "/" + rel; }

Project read(const std::string &rel) {
  auto r = readProject(real(rel));
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? std::move(r.value()) : Project();
}

int count(const Project &p, int type) {
  int n = 0;
  for (const auto &[i, r] : p.rungs)
    for (const auto &col : r.cells)
      for (const auto &c : col) n += c.type == type;
  return n;
}

} // namespace

TEST(ClRealProjects, AllRead) {
  int n = 0;
  for (const auto &e : fs::recursive_directory_iterator(LJ_CL_REAL_DIR)) {
    std::string ext = e.path().extension().string();
    if (ext != ".clp" && ext != ".clprj") continue;
    auto r = readProject(e.path().string());
    ++n;
    // The one refusal: an upstream .clp whose operate uses a character constant 'E', which
    // LinuxCNC 2.9 reports as a syntax error on every scan (only master reads it).
    if (e.path().filename() == "IndexedVar_used_in_function.clp" &&
        e.path().parent_path().filename() == "upstream_mavati56") {
      ASSERT_FALSE(r.ok());
      EXPECT_NE(r.status().message().find(
                    "IndexedVar_used_in_function.clp:60: error: arithmetic_expressions.csv "
                    "expression 4 (used by the operate block at rung 3 row 0 column 9): "
                    "'@200/0@:='E'' column 10: ''' where a value is expected"),
                std::string::npos)
          << r.status().message();
      continue;
    }
    EXPECT_TRUE(r.ok()) << r.status().message();
  }
  EXPECT_EQ(n, 63); // 30 .clp and 33 .clprj
}

TEST(ClRealProjects, EcSim) {
  Project p = read("linuxcnc/history/configs/ec-sim/ec-sim-ladder.clp");
  ASSERT_EQ(p.sections.size(), 3u);
  EXPECT_EQ(p.sections[0].subRoutine, -1);
  EXPECT_EQ(p.sections[0].firstRung, 4);
  EXPECT_EQ(p.sections[0].lastRung, 87);
  EXPECT_EQ(p.sections[1].subRoutine, 0);
  EXPECT_EQ(p.sections[1].firstRung, 24);
  EXPECT_EQ(p.sections[2].subRoutine, 1);
  EXPECT_EQ(p.sections[2].lastRung, 40);
  EXPECT_EQ(p.rungs.size(), 87u);
  ASSERT_GE(p.timersIec.size(), 2u);
  EXPECT_EQ(p.timersIec[0].baseMs, 60000);
  EXPECT_EQ(p.timersIec[0].preset, 15);
  ASSERT_GE(p.timersIec.size(), 3u); // the file is 0,15,0 / 0,15,0 / 1,2,0 / 1,2,0 ...
  EXPECT_EQ(p.timersIec[2].baseMs, 1000);
  EXPECT_EQ(p.timersIec[2].preset, 2);
  EXPECT_EQ(p.timersIec[2].mode, IecMode::Ton);
  EXPECT_EQ(count(p, 13), 19); // TM 19
  EXPECT_EQ(count(p, 20), 9);  // CMP 9
  EXPECT_EQ(count(p, 60), 20); // OP 20
  EXPECT_EQ(count(p, 55), 2);  // call 2
  // rung 44: a contact followed by empty cells, coil %Q83 (surprise 1), and the counter
  const Rung &r44 = p.rungs.at(44);
  EXPECT_EQ(r44.at(0, 1).type, 1);
  EXPECT_EQ(r44.at(0, 1).varType, 60);
  EXPECT_EQ(r44.at(0, 1).varNum, 80);
  EXPECT_EQ(r44.at(1, 1).type, 0);
  EXPECT_EQ(r44.at(9, 1).type, 50);
  EXPECT_EQ(r44.at(9, 1).varNum, 83);
  EXPECT_EQ(r44.at(4, 2).type, 12);
  EXPECT_EQ(count(p, 12), 1); // C 1
}

TEST(ClRealProjects, DemoMazakChainAndEraserCells) {
  Project p = read("linuxcnc/configs/attic/demo_mazak/demo_mazak.clp");
  ASSERT_EQ(p.sections.size(), 1u);
  EXPECT_EQ(p.sections[0].order.front(), 8);
  EXPECT_EQ(p.sections[0].order.back(), 5);
  EXPECT_EQ(count(p, 103), 6); // type 103 x6 kept, acting as FREE
  EXPECT_EQ(count(p, 10), 10); // T 10
  // %T10 and %T11 with SIZE_NBR_TIMERS=10: read, with the size they need noted (and warnings)
  EXPECT_EQ(p.sizes.timers, 10);
  EXPECT_EQ(p.needed.timers, 12);
  EXPECT_FALSE(p.warnings.empty());
}

TEST(ClRealProjects, ExampleBlocks) {
  Project p = read("linuxcnc/src/hal/classicladder/projects_examples/example.clp");
  const Rung &r0 = p.rungs.at(0);
  EXPECT_EQ(r0.at(3, 1).type, 13); // IEC timer alive at its top-right cell
  EXPECT_EQ(r0.at(2, 1).type, 99);
  EXPECT_EQ(r0.at(2, 2).type, 99);
  EXPECT_EQ(r0.at(3, 2).type, 99);
  const Rung &r1 = p.rungs.at(1);
  EXPECT_EQ(r1.at(3, 0).type, 10);
  EXPECT_EQ(r1.at(3, 0).varNum, 3);
  EXPECT_TRUE(r1.at(2, 1).connectedWithTop); // C wired to E
}

TEST(ClRealProjects, EstopTimers) {
  Project p = read("linuxcnc/configs/common/configurable_options/ladder/estop.clp");
  ASSERT_GE(p.timers.size(), 5u);
  EXPECT_EQ(p.timers[0].baseMs, 1000);
  EXPECT_EQ(p.timers[0].preset, 10);
  EXPECT_EQ(p.timers[2].baseMs, 60000);
  EXPECT_EQ(p.timers[2].preset, 20);
  EXPECT_EQ(p.timers[3].baseMs, 100);
}

TEST(ClRealProjects, Sequential) {
  Project p = read("linuxcnc/src/hal/classicladder/projects_examples/example_sequential.clp");
  EXPECT_EQ(p.sequential.steps.size(), 10u);
  EXPECT_EQ(p.sequential.transitions.size(), 10u);
  const Transition &t0 = p.sequential.transitions[0];
  EXPECT_EQ(t0.slot, 0);
  EXPECT_EQ(t0.activate, (std::vector<int32_t>{8, 9})); // AND divergence
  EXPECT_EQ(t0.deactivate, (std::vector<int32_t>{0}));
  EXPECT_EQ(t0.condition.type, 0); // C0,0,0/1: %B1
  EXPECT_EQ(t0.condition.num, 1);
  EXPECT_TRUE(p.sequential.steps[0].initial);
  bool seqSection = false;
  for (const auto &s : p.sections) seqSection |= s.language == Language::Sequential;
  EXPECT_TRUE(seqSection);
}

TEST(ClRealProjects, Upstream09) {
  Project p = read("upstream_mavati56/DemousComplet.clprj");
  EXPECT_EQ(p.flavor, Flavor::Upstream09);
  ASSERT_FALSE(p.rungs.empty());
  EXPECT_EQ(p.rungs.begin()->second.cells.size(), 12u);
  EXPECT_EQ(p.rungs.begin()->second.cells[0].size(), 8u);
  EXPECT_EQ(p.rungs.size(), 57u);
}
