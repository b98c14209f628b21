// The editor's grid (ladder/Grid.h) and its evaluator (ladder/GridEval.h): expected values from
// the drawing rules (docs/ladder-edit.md "Grid and oracle"): power enters every row at the left
// rail, passes a closed contact or a line, spreads along a vertical line, reaches the outputs.
#include "ladder/Grid.h"
#include "ladder/GridEval.h"
#include "ladder/Layout.h"
#include "pipeline/Dialects.h"

#include <gtest/gtest.h>

namespace lj::ladder {
namespace {

GridCell cell(CellKind k, std::string operand = {}) {
  GridCell c;
  c.kind = k;
  c.operand = std::move(operand);
  return c;
}

const DialectText &dialect(const char *name) { return pipeline::dialectNamed(name)->text(); }

OperandCheck checkFor(const char *name) {
  const pipeline::Dialect *d = pipeline::dialectNamed(name);
  return [d](CellKind, const std::string &operand, std::string &error) {
    return d->parseAddress(operand, error).has_value();
  };
}

/// A rung of one row: the cells left to right, then lines up to the output in the last column.
GridRung row(std::vector<GridCell> inputs, GridCell output, int cols = 4) {
  GridRung g = GridRung::blank(1, cols);
  for (size_t i = 0; i < inputs.size(); ++i) g.at(0, static_cast<int>(i)) = inputs[i];
  for (int c = static_cast<int>(inputs.size()); c + 1 < cols; ++c) g.at(0, c).kind = CellKind::Wire;
  g.at(0, cols - 1) = output;
  return g;
}

std::string text(const std::vector<GridRung> &rungs, const char *d = "hnc8",
                 std::vector<GridError> *errs = nullptr) {
  std::vector<GridPart> parts{{"PLC1", rungs}};
  std::string out;
  std::vector<GridError> errors;
  bool ok = gridProgramText(parts, dialect(d), checkFor(d), {}, out, errors);
  if (errs) *errs = errors;
  EXPECT_EQ(ok, errors.empty());
  return ok ? out : std::string();
}

std::vector<GridError> errorsOf(const GridRung &g) {
  std::vector<GridError> errors;
  text({g}, "hnc8", &errors);
  EXPECT_FALSE(errors.empty()) << gridText(g);
  return errors;
}

/// One scan of `rungs` with `in` set, from the image `bits`.
class Eval {
public:
  explicit Eval(std::vector<GridRung> rungs) : parts_{{"PLC1", std::move(rungs)}} {
    std::string error;
    EXPECT_TRUE(eval_.load(parts_, error)) << error;
  }
  bool scan(std::initializer_list<std::pair<const char *, bool>> in, const char *out) {
    for (auto [a, v] : in) bits_[a] = v;
    eval_.scan(bits_);
    return bits_[out];
  }

private:
  std::vector<GridPart> parts_;
  GridEvaluator eval_;
  BitImage bits_;
};

TEST(Grid, SeriesIsAnd) {
  GridRung g = row({cell(CellKind::ContactNO, "X0.0"), cell(CellKind::ContactNO, "X0.1")},
                   cell(CellKind::Coil, "Y0.0"));
  EXPECT_EQ(text({g}), "LD X0.0\nAND X0.1\nOUT Y0.0\n");
  Eval e({g});
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      EXPECT_EQ(e.scan({{"X0.0", a}, {"X0.1", b}}, "Y0.0"), a && b) << a << b;
}

TEST(Grid, VerticalLineMakesAParallel) {
  // |--[X0.0]--+--[X0.2]--(Y0.0)
  // |--[X0.1]--+
  GridRung g = row({cell(CellKind::ContactNO, "X0.0"), cell(CellKind::ContactNO, "X0.2")},
                   cell(CellKind::Coil, "Y0.0"));
  g.insertRow(1);
  g.at(1, 0) = cell(CellKind::ContactNO, "X0.1");
  g.setLink(0, 1, true);
  EXPECT_EQ(text({g}), "LD X0.0\nOR X0.1\nAND X0.2\nOUT Y0.0\n");
  Eval e({g});
  for (int m = 0; m < 8; ++m) {
    bool a = m & 1, b = m & 2, c = m & 4;
    EXPECT_EQ(e.scan({{"X0.0", a}, {"X0.1", b}, {"X0.2", c}}, "Y0.0"), (a || b) && c) << m;
  }
  // Without the vertical line the lower contact leads nowhere.
  g.setLink(0, 1, false);
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].row, 1);
  EXPECT_EQ(errs[0].col, 0);
  EXPECT_NE(errs[0].message.find("unconnected"), std::string::npos) << errs[0].text();
}

TEST(Grid, NormallyClosedAndNegatedCoil) {
  GridRung nc = row({cell(CellKind::ContactNC, "X0.0")}, cell(CellKind::Coil, "Y0.0"));
  GridRung neg = row({cell(CellKind::ContactNO, "X0.0")}, cell(CellKind::CoilNot, "Y0.1"));
  EXPECT_EQ(text({nc, neg}), "LDI X0.0\nOUT Y0.0\nLD X0.0\nOOUT Y0.1\n");
  Eval e({nc, neg});
  EXPECT_TRUE(e.scan({{"X0.0", false}}, "Y0.0"));
  EXPECT_FALSE(e.scan({{"X0.0", true}}, "Y0.0"));
  EXPECT_TRUE(e.scan({{"X0.0", false}}, "Y0.1"));
  EXPECT_FALSE(e.scan({{"X0.0", true}}, "Y0.1"));
}

TEST(Grid, SetResetLatchAcrossTicks) {
  GridRung set = row({cell(CellKind::ContactNO, "X0.0")}, cell(CellKind::Set, "Y0.0"));
  GridRung rst = row({cell(CellKind::ContactNO, "X0.1")}, cell(CellKind::Reset, "Y0.0"));
  EXPECT_EQ(text({set, rst}), "LD X0.0\nSET Y0.0\nLD X0.1\nRST Y0.0\n");
  Eval e({set, rst});
  EXPECT_FALSE(e.scan({{"X0.0", false}, {"X0.1", false}}, "Y0.0"));
  EXPECT_TRUE(e.scan({{"X0.0", true}, {"X0.1", false}}, "Y0.0"));
  EXPECT_TRUE(e.scan({{"X0.0", false}, {"X0.1", false}}, "Y0.0")); // held
  EXPECT_FALSE(e.scan({{"X0.0", false}, {"X0.1", true}}, "Y0.0"));
  EXPECT_FALSE(e.scan({{"X0.0", true}, {"X0.1", true}}, "Y0.0")); // reset rung is later
  EXPECT_FALSE(e.scan({{"X0.0", false}, {"X0.1", false}}, "Y0.0"));
}

TEST(Grid, RisingEdgeConductsOneScan) {
  GridRung g = row({cell(CellKind::ContactRise, "X0.0")}, cell(CellKind::Coil, "Y0.0"));
  EXPECT_EQ(text({g}), "LDP X0.0\nOUT Y0.0\n");
  Eval e({g});
  EXPECT_FALSE(e.scan({{"X0.0", false}}, "Y0.0"));
  EXPECT_TRUE(e.scan({{"X0.0", true}}, "Y0.0"));
  EXPECT_FALSE(e.scan({{"X0.0", true}}, "Y0.0"));
  EXPECT_FALSE(e.scan({{"X0.0", false}}, "Y0.0"));
  EXPECT_TRUE(e.scan({{"X0.0", true}}, "Y0.0"));
}

TEST(Grid, FanOutToTwoOutputs) {
  // |--[X0.0]--+---------(Y0.0)
  //            +--[X0.1]--(Y0.1)
  GridRung g = row({cell(CellKind::ContactNO, "X0.0")}, cell(CellKind::Coil, "Y0.0"));
  g.insertRow(1);
  g.at(1, 1) = cell(CellKind::ContactNO, "X0.1");
  g.at(1, 2).kind = CellKind::Wire;
  g.at(1, 3) = cell(CellKind::Coil, "Y0.1");
  g.setLink(0, 1, true);
  EXPECT_EQ(text({g}), "LD X0.0\nOUT Y0.0\nAND X0.1\nOUT Y0.1\n");
  Eval e({g});
  EXPECT_FALSE(e.scan({{"X0.0", false}, {"X0.1", true}}, "Y0.1"));
  EXPECT_TRUE(e.scan({{"X0.0", true}, {"X0.1", true}}, "Y0.1"));
  EXPECT_TRUE(e.scan({{"X0.0", true}, {"X0.1", false}}, "Y0.0"));
  EXPECT_FALSE(e.scan({{"X0.0", true}, {"X0.1", false}}, "Y0.1"));
}

TEST(Grid, OtherDialectsPrintTheirOwnWords) {
  GridRung g = row({cell(CellKind::ContactNC, "X0.0"), cell(CellKind::ContactNO, "R0.1")},
                   cell(CellKind::CoilNot, "Y0.0"));
  EXPECT_EQ(text({g}, "fanuc"), "RD.NOT X0.0\nAND R0.1\nWRT.NOT Y0.0\n");
  GridRung i = row({cell(CellKind::ContactNC, "%I0.0"), cell(CellKind::ContactNO, "%M1")},
                   cell(CellKind::Set, "%Q0.0"));
  EXPECT_EQ(text({i}, "iec"), "LDN %I0.0\nAND %M1\nS %Q0.0\n");
}

TEST(Grid, FanucFanOutNeedingABranchStackIsRefusedOnItsBranch) {
  // |--[X0.0]--+--[X0.1]--(Y0.0)      HNC-8: MPS / MPP; FANUC PMC mnemonics have no branch
  //            +--[X0.2]--(Y0.1)      stack, so the first branch is refused on its contact.
  GridRung g = GridRung::blank(2, 4);
  g.at(0, 0) = cell(CellKind::ContactNO, "X0.0");
  g.at(0, 1) = cell(CellKind::ContactNO, "X0.1");
  g.at(0, 2).kind = CellKind::Wire;
  g.at(0, 3) = cell(CellKind::Coil, "Y0.0");
  g.at(1, 1) = cell(CellKind::ContactNO, "X0.2");
  g.at(1, 2).kind = CellKind::Wire;
  g.at(1, 3) = cell(CellKind::Coil, "Y0.1");
  g.setLink(0, 1, true);
  EXPECT_EQ(text({g}), "LD X0.0\nMPS\nAND X0.1\nOUT Y0.0\nMPP\nAND X0.2\nOUT Y0.1\n");
  std::vector<GridError> errs;
  text({g}, "fanuc", &errs);
  ASSERT_EQ(errs.size(), 1u);
  EXPECT_EQ(errs[0].row, 0);
  EXPECT_EQ(errs[0].col, 1);
  EXPECT_NE(errs[0].message.find("branch stack"), std::string::npos) << errs[0].text();
}

TEST(Grid, ElementAfterAnOutputIsRefusedOnItsCell) {
  GridRung g = GridRung::blank(1, 4);
  g.at(0, 0) = cell(CellKind::ContactNO, "X0.0");
  g.at(0, 1) = cell(CellKind::Coil, "Y0.0");
  g.at(0, 2) = cell(CellKind::ContactNO, "X0.1");
  g.at(0, 3) = cell(CellKind::Coil, "Y0.1");
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].part, "PLC1");
  EXPECT_EQ(errs[0].rung, 1);
  EXPECT_EQ(errs[0].row, 0);
  EXPECT_EQ(errs[0].col, 2);
  EXPECT_NE(errs[0].message.find("不可以加后置"), std::string::npos) << errs[0].text();
  EXPECT_EQ(errs[0].text().rfind("PLC1 rung 1 row 1 column 3: ", 0), 0u) << errs[0].text();
}

TEST(Grid, ShortCircuitIsRefused) {
  // Lines only from the rail to the output.
  GridRung g = row({}, cell(CellKind::Coil, "Y0.0"));
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].col, 3);
  EXPECT_NE(errs[0].message.find("short circuit"), std::string::npos) << errs[0].text();
  // A line in parallel with a contact bridges it.
  GridRung p = row({cell(CellKind::ContactNO, "X0.0"), cell(CellKind::ContactNO, "X0.1")},
                   cell(CellKind::Coil, "Y0.0"));
  p.insertRow(1);
  p.at(1, 1).kind = CellKind::Wire;
  p.setLink(0, 1, true);
  p.setLink(0, 2, true);
  errs = errorsOf(p);
  EXPECT_EQ(errs[0].row, 1);
  EXPECT_EQ(errs[0].col, 1);
  EXPECT_NE(errs[0].message.find("short circuit"), std::string::npos) << errs[0].text();
}

TEST(Grid, BoxWithoutInputIsRefused) {
  GridRung g = GridRung::blank(1, 4);
  g.at(0, 2).kind = CellKind::Box;
  g.at(0, 2).instr = "MOV";
  g.at(0, 2).operands = {"D0", "D1"};
  g.at(0, 3).kind = CellKind::BoxPart;
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].col, 2);
  EXPECT_NE(errs[0].message.find("no power from the left rail"), std::string::npos)
      << errs[0].text();
}

TEST(Grid, BridgeHasNoSeriesParallelForm) {
  // X0.1 parts from X0.0 (joined at boundary 1, each to its own output), and X0.2's right end
  // is joined to X0.3's row: power of X0.3 would have to flow back into the shared part.
  std::vector<GridError> errs;
  GridRung b = GridRung::blank(3, 4);
  b.at(0, 0) = cell(CellKind::ContactNO, "X0.0");
  b.at(0, 1).kind = CellKind::Wire;
  b.at(0, 2).kind = CellKind::Wire;
  b.at(0, 3) = cell(CellKind::Coil, "Y0.0");
  b.at(1, 0) = cell(CellKind::ContactNO, "X0.1");
  b.at(1, 1) = cell(CellKind::ContactNO, "X0.2");
  b.at(1, 2).kind = CellKind::Wire;
  b.at(1, 3) = cell(CellKind::Coil, "Y0.1");
  b.at(2, 0) = cell(CellKind::ContactNO, "X0.3");
  b.at(2, 1).kind = CellKind::Wire;
  b.at(2, 2).kind = CellKind::Wire;
  b.at(2, 3) = cell(CellKind::Coil, "Y0.2");
  b.setLink(0, 1, true); // X0.0 and X0.1 meet
  b.setLink(1, 2, true); // X0.2's right joins X0.3's row: (X0.0|X0.1)&X0.2 | X0.3 ...
  errs = errorsOf(b);
  bool bridge = false;
  for (const GridError &e : errs)
    bridge = bridge || e.message.find("no series/parallel form") != std::string::npos;
  EXPECT_TRUE(bridge) << errs[0].text();
}

TEST(Grid, BoxAtTheRightRail) {
  GridRung g = row({cell(CellKind::ContactNO, "X0.0")}, cell(CellKind::Box), 4);
  g.at(0, 2) = g.at(0, 3); // the box spans the last two columns
  g.at(0, 2).instr = "MOV";
  g.at(0, 2).operands = {"D0", "D1"};
  g.at(0, 3) = cell(CellKind::BoxPart);
  EXPECT_EQ(text({g}), "LD X0.0\nMOV D0 D1\n");
  g.at(0, 2).instr = "NOSUCH";
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].col, 2);
  EXPECT_NE(errs[0].message.find("no instruction of the hnc8 dialect"), std::string::npos)
      << errs[0].text();
}

TEST(Grid, OperandsAreCheckedByTheDialect) {
  GridRung g = row({cell(CellKind::ContactNO, "Q9.9")}, cell(CellKind::Coil, "Y0.0"));
  std::vector<GridError> errs = errorsOf(g);
  EXPECT_EQ(errs[0].col, 0);
  EXPECT_NE(errs[0].message.find("Q9.9"), std::string::npos) << errs[0].text();
  GridRung none = row({cell(CellKind::ContactNO, "")}, cell(CellKind::Coil, "Y0.0"));
  errs = errorsOf(none);
  EXPECT_NE(errs[0].message.find("no address"), std::string::npos) << errs[0].text();
}

TEST(Grid, NetworkToGridPlacesAsTheView) {
  Diagnostics diags("t.stl");
  std::optional<VerifiedProgram> p = pipeline::dialectNamed("hnc8")->compile(
      "LD X0.0\nOR X0.1\nAND X0.2\nOUT Y0.0\n", "t.stl", VerifyOptions{}, diags, nullptr);
  ASSERT_TRUE(p) << diags.render();
  Networks nets = fromProgram(*p);
  ASSERT_EQ(nets.parts.size(), 1u);
  GridRung g;
  std::string error;
  ASSERT_TRUE(gridOfRung(nets.parts[0].rungs[0], g, error)) << error;
  // Inputs in columns 0..6 (the editor's fixed input width, kMinInputCols), the output right.
  ASSERT_EQ(g.rows, 2);
  ASSERT_EQ(g.cols, kMinInputCols + 1);
  EXPECT_EQ(g.at(0, 0), cell(CellKind::ContactNO, "X0.0"));
  EXPECT_EQ(g.at(1, 0), cell(CellKind::ContactNO, "X0.1"));
  EXPECT_EQ(g.at(0, 1), cell(CellKind::ContactNO, "X0.2"));
  EXPECT_TRUE(g.link(0, 1));
  for (int c = 2; c < kMinInputCols; ++c) EXPECT_EQ(g.at(0, c).kind, CellKind::Wire) << c;
  EXPECT_EQ(g.at(0, kMinInputCols), cell(CellKind::Coil, "Y0.0"));
  // ...and back: the same program.
  EXPECT_EQ(text({g}), "LD X0.0\nOR X0.1\nAND X0.2\nOUT Y0.0\n");
}

TEST(Grid, InsertAndDeleteRowsAndColumns) {
  GridRung g = row({cell(CellKind::ContactNO, "X0.0")}, cell(CellKind::Coil, "Y0.0"));
  g.insertRow(1);
  g.at(1, 0) = cell(CellKind::ContactNO, "X0.1");
  g.setLink(0, 1, true);
  g.insertColumn(0);
  EXPECT_EQ(g.cols, 5);
  EXPECT_EQ(g.at(0, 1), cell(CellKind::ContactNO, "X0.0"));
  EXPECT_TRUE(g.link(0, 2));
  g.deleteColumn(0);
  EXPECT_EQ(g.cols, 4);
  EXPECT_TRUE(g.link(0, 1));
  g.deleteRow(1);
  EXPECT_EQ(g.rows, 1);
  EXPECT_EQ(text({g}), "LD X0.0\nOUT Y0.0\n");
}

TEST(GridEval, BoxIsOutsideTheEvaluator) {
  GridRung g = GridRung::blank(1, 3);
  g.at(0, 0) = cell(CellKind::ContactNO, "X0.0");
  g.at(0, 1).kind = CellKind::Box;
  g.at(0, 2).kind = CellKind::BoxPart;
  std::vector<GridPart> parts{{"PLC1", {g}}};
  GridEvaluator e;
  std::string error;
  EXPECT_FALSE(e.load(parts, error));
  EXPECT_EQ(error.rfind("PLC1 rung 1 row 1 column 2: ", 0), 0u) << error;
}

} // namespace
} // namespace lj::ladder
