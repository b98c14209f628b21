// The dialect and profile registries (pipeline/Dialects.h, profiles/Profiles.h): which dialect a
// PROGRAM is read in (--dialect, else its extension, else HNC-8; a ladder JSON names its own),
// and the usage errors for an unknown dialect (CLI.md, docs/architecture.md).
#include "pipeline/Dialects.h"
#include "pipeline/ProgramFile.h"
#include "profiles/Profiles.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace lj::pipeline {
namespace {

TEST(Profiles, RegistryHoldsHnc8ByName) {
  ASSERT_EQ(allProfiles().size(), 4u); // hnc8, fanuc, iec, classicladder
  const TargetProfile *p = profileNamed("hnc8");
  ASSERT_NE(p, nullptr);
  EXPECT_STREQ(p->name, "hnc8");
  EXPECT_EQ(profileNamed("siemens"), nullptr);
  EXPECT_EQ(profileNamed(""), nullptr);
  // DIALECT.md 1: X is the input area, D the 32-bit registers; T numbers 0..127 and 300..427.
  EXPECT_EQ(p->areaFromLetter('x'), Area::Input);
  EXPECT_EQ(p->bitWidth(Area::DWord), 32);
  EXPECT_TRUE(p->validIndex(Area::Timer, 300));
  EXPECT_FALSE(p->validIndex(Area::Timer, 200));
  // The CNC table comes with the profile: one row per family-Cnc operation.
  EXPECT_NE(p->cncRow(Op::ChannelModeSet), nullptr);
  EXPECT_EQ(p->cncRow(Op::Coil), nullptr);
}

TEST(Dialects, Hnc8FanucIecAndClassicLadderAreRegisteredWithTheirProfiles) {
  ASSERT_EQ(allDialects().size(), 4u);
  EXPECT_EQ(dialectNamed("hnc8"), &defaultDialect());
  EXPECT_EQ(defaultDialect().profile, profileNamed("hnc8"));
  ASSERT_NE(dialectNamed("fanuc"), nullptr);
  EXPECT_EQ(dialectNamed("fanuc")->profile, profileNamed("fanuc"));
  ASSERT_NE(dialectNamed("iec"), nullptr);
  EXPECT_EQ(dialectNamed("iec")->profile, profileNamed("iec"));
  ASSERT_NE(dialectNamed("classicladder"), nullptr); // docs/classicladder.md
  EXPECT_EQ(dialectNamed("classicladder")->profile, profileNamed("classicladder"));
  EXPECT_EQ(dialectNamed("HNC8"), nullptr); // names are exact
  EXPECT_EQ(knownDialects(), "hnc8, fanuc, iec, classicladder");
}

TEST(Profiles, FanucAreasAreBytesWithUpperRanges) {
  const TargetProfile *p = profileNamed("fanuc");
  ASSERT_NE(p, nullptr);
  // fanuc-pmc.md 1: T0..T499 and T9000..T9499; D0..D9999; bytes, little-endian (3.1).
  EXPECT_EQ(p->areaFromName("t"), Area::TimerData);
  EXPECT_TRUE(p->validIndex(Area::TimerData, 9499));
  EXPECT_FALSE(p->validIndex(Area::TimerData, 500));
  EXPECT_EQ(p->elementOffset(Area::TimerData, 9000), p->elementOffset(Area::TimerData, 499) + 1);
  EXPECT_TRUE(p->validSpan(Area::DataTable, 9998, 2));
  EXPECT_FALSE(p->validSpan(Area::DataTable, 9999, 2));
  EXPECT_FALSE(p->validSpan(Area::TimerData, 499, 2)); // T499..T500 crosses out of the range
  EXPECT_EQ(p->bitWidth(Area::Relay), 8);
}

TEST(Profiles, IecProfileHasPerObjectEdgesAndNoCncTable) {
  const TargetProfile *p = profileNamed("iec");
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p->edgePolicy, EdgePolicy::PerObject); // modicon-neza.md 2.1, 12.1
  EXPECT_EQ(p->maxBranchDepth, 8);                 // MPS depth, L979
  EXPECT_EQ(p->cncRow(Op::ChannelModeSet), nullptr);
  EXPECT_TRUE(p->validIndex(Area::Timer, 31)); // %TM0..%TM31 (L1269)
  EXPECT_FALSE(p->validIndex(Area::Timer, 32));
}

/// The dialect a Result holds, nullptr when it holds an error.
const Dialect *held(const Result<const Dialect *> &r) { return r ? r.value() : nullptr; }

TEST(Dialects, ExtensionChoosesTheDialect) {
  EXPECT_EQ(held(dialectForPath("a/b/prog.stl")), &defaultDialect());
  EXPECT_EQ(held(dialectForPath("PROG.STL")), &defaultDialect());
  EXPECT_EQ(held(dialectForPath("plc.dit")), &defaultDialect());
  // An unknown extension keeps the behaviour from before dialects: HNC-8 STL.
  EXPECT_EQ(held(dialectForPath("prog.txt")), &defaultDialect());
  EXPECT_EQ(held(dialectForPath("prog")), &defaultDialect());
  EXPECT_EQ(held(dialectForPath("spindle.pmc")), dialectNamed("fanuc"));
  EXPECT_EQ(held(dialectForPath("SPINDLE.PMC")), dialectNamed("fanuc"));
  EXPECT_EQ(held(dialectForPath("x.il")), dialectNamed("iec"));
  EXPECT_EQ(held(dialectForPath("estop.clp")), dialectNamed("classicladder"));
  EXPECT_EQ(held(dialectForPath("X.IL")), dialectNamed("iec"));
}

TEST(Dialects, OptionNamesTheDialect) {
  EXPECT_EQ(held(dialectForOption("hnc8")), &defaultDialect());
  EXPECT_EQ(held(dialectForOption("fanuc")), dialectNamed("fanuc"));
  EXPECT_EQ(held(dialectForOption("iec")), dialectNamed("iec"));
  Result<const Dialect *> unknown = dialectForOption("siemens");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.status().code(), ErrorCode::InvalidArgument);
  EXPECT_EQ(unknown.status().message(),
            "unknown dialect 'siemens' (known: hnc8, fanuc, iec, classicladder)");
}

TEST(Dialects, LadderJsonNamesItsDialect) {
  EXPECT_EQ(held(dialectOfJson(R"({"format":"ladderjit-ladder","dialect":"hnc8"})")),
            &defaultDialect());
  EXPECT_EQ(held(dialectOfJson(R"({"format":"ladderjit-ladder","dialect":"iec"})")),
            dialectNamed("iec"));
  Result<const Dialect *> unknown = dialectOfJson(R"({"dialect":"xyz"})");
  ASSERT_FALSE(unknown);
  EXPECT_EQ(unknown.status().code(), ErrorCode::InvalidArgument);
  EXPECT_EQ(unknown.status().message(),
            "ladder JSON: unknown dialect 'xyz' (known: hnc8, fanuc, iec, classicladder)");
}

std::string tempFile(const std::string &name, const std::string &text) {
  std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(Dialects, ReadProgramFileRecordsAndRefusesDialects) {
  const std::string stl = tempFile("dialect_ok.stl", "LD X0.0\nOUT Y0.0\n");
  ProgramSource src;
  Status st = readProgramFile(stl, src);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(src.dialect, &defaultDialect());
  ProgramSource viaOption;
  st = readProgramFile(stl, viaOption, "hnc8");
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(viaOption.dialect, &defaultDialect());
  std::string diags;
  std::optional<VerifiedProgram> prog = verifyProgram(src, 200, diags);
  ASSERT_TRUE(prog) << diags;
  EXPECT_EQ(prog->profile, profileNamed("hnc8")); // the verified program carries its profile

  ProgramSource refused;
  st = readProgramFile(stl, refused, "cobol");
  EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
  EXPECT_EQ(st.message(), "unknown dialect 'cobol' (known: hnc8, fanuc, iec, classicladder)");
  // --dialect hnc8 reads a .pmc name as HNC-8 STL; without it the .pmc is FANUC text.
  const std::string pmc = tempFile("dialect_as.pmc", "LD X0.0\nOUT Y0.0\n");
  ProgramSource asFanuc;
  st = readProgramFile(pmc, asFanuc);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(asFanuc.dialect, dialectNamed("fanuc"));
  EXPECT_FALSE(verifyProgram(asFanuc, 200, diags)); // LD is no PMC instruction
  ProgramSource forced;
  st = readProgramFile(pmc, forced, "hnc8");
  EXPECT_TRUE(st.ok()) << st.message();
}

// The kinds of failure a caller can tell apart (ir/Status.h), each naming the file.
TEST(Dialects, ReadProgramFileErrorsSayWhatKind) {
  ProgramSource src;
  const std::string missing = ::testing::TempDir() + "dialect_no_such_file.stl";
  Status st = readProgramFile(missing, src);
  EXPECT_EQ(st.code(), ErrorCode::NotFound);
  EXPECT_EQ(st.loc().file, missing);
  EXPECT_NE(st.message().find(missing), std::string::npos) << st.message();
  // A .dit name is a container: without its magic line it is damaged, not STL.
  const std::string dit = tempFile("dialect_damaged.dit", "LD X0.0\nOUT Y0.0\n");
  st = readProgramFile(dit, src);
  EXPECT_EQ(st.code(), ErrorCode::BadFormat);
  EXPECT_EQ(st.loc().file, dit);
  // A ladder JSON naming a dialect this build does not have.
  const std::string json = tempFile("dialect_xyz.json", R"({"dialect":"xyz"})");
  st = readProgramFile(json, src);
  EXPECT_EQ(st.code(), ErrorCode::InvalidArgument);
  EXPECT_EQ(st.message(), json + ": ladder JSON: unknown dialect 'xyz' (known: hnc8, fanuc, iec, "
                                 "classicladder)");
}

} // namespace
} // namespace lj::pipeline
