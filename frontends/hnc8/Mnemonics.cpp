// The HNC-8 mnemonic table (hnc8-core.md 5.1, hnc8-functions-1.md 6, hnc8-functions-2.md 5,
// hnc8-cnc-interface.md 4): spelling -> semantic Op, aliases as a column (DIALECT.md 2).
#include "frontends/hnc8/Mnemonics.h"

#include "frontends/hnc8/Address.h"
#include "frontends/hnc8/FrontEnd.h"

#include <cctype>
#include <string>
#include <unordered_map>

namespace lj::hnc8 {

namespace {

constexpr MnemonicRow kRows[] = {
    {Op::Load, "LD", nullptr},
    {Op::LoadNot, "LDI", nullptr},
    {Op::LoadTrue, "LDT", nullptr},
    {Op::LoadRise, "LDP", nullptr},
    {Op::LoadFall, "LDF", nullptr},
    {Op::And, "AND", nullptr},
    {Op::AndNot, "ANI", nullptr},
    {Op::Or, "OR", nullptr},
    {Op::OrNot, "ORI", nullptr},
    {Op::AndRise, "ANDP", nullptr},
    {Op::AndFall, "ANDF", nullptr},
    {Op::OrRise, "ORP", nullptr},
    {Op::OrFall, "ORF", nullptr},
    {Op::AndBlock, "ANB", nullptr},
    {Op::OrBlock, "ORB", nullptr},
    {Op::BranchPush, "MPS", nullptr},
    {Op::BranchRead, "MRD", nullptr},
    {Op::BranchPop, "MPP", nullptr},
    {Op::Coil, "OUT", "WRT"},
    {Op::CoilNot, "OOUT", nullptr},
    {Op::Set, "SET", nullptr},
    {Op::Reset, "RST", nullptr},
    {Op::EndInit, "IEND", nullptr},
    {Op::EndCyclic, "1END", "END1"},
    {Op::EndSliced, "2END", "END2"},
    {Op::Jump, "JMP", nullptr},
    {Op::Label, "LBL", nullptr},
    {Op::Call, "CALL", nullptr},
    {Op::SubBegin, "SP", nullptr},
    {Op::SubEnd, "SPE", nullptr},
    {Op::Return, "RETN", nullptr},
    {Op::LoopBegin, "LOOP", nullptr},
    {Op::LoopEnd, "NEXT", nullptr},
    {Op::Add, "ADD", nullptr},
    {Op::Subtract, "SUB", nullptr},
    {Op::Multiply, "MUL", nullptr},
    {Op::Divide, "DIV", nullptr},
    {Op::Increment, "INC", nullptr},
    {Op::Decrement, "DEC", nullptr},
    {Op::BitAnd, "WAND", nullptr},
    {Op::BitOr, "WOR", nullptr},
    {Op::BitXor, "WXOR", nullptr},
    {Op::Negate, "NEG", nullptr},
    {Op::CompareLe, "CMP", nullptr},
    {Op::CompareLt, "LT", nullptr},
    {Op::CompareRange, "ACMP", nullptr},
    {Op::CompareEq, "COIN", nullptr},
    {Op::Move, "MOV", nullptr},
    {Op::RegisterCounter, "CTR", nullptr},
    {Op::RingCounter, "CTRC", nullptr},
    {Op::UpDownCounter, "CTUD", nullptr},
    {Op::OnDelayTimer, "TMRB", nullptr},
    {Op::OffDelayTimer, "STMR", nullptr},
    {Op::RisePulse, "PLS", nullptr},
    {Op::FallPulse, "PLF", nullptr},
    {Op::Toggle, "ALT", nullptr},
    {Op::IndexedMove, "XMOV", nullptr},
    {Op::BlockMove, "BMOV", nullptr},
    {Op::Fill, "FMOV", nullptr},
    {Op::Exchange, "XCH", nullptr},
    {Op::ZoneReset, "ZRST", nullptr},
    {Op::TableEncode, "ENCO", nullptr},
    {Op::TableDecode, "DECO", nullptr},
    {Op::TableLookup, "COD", nullptr},
    {Op::TableSearch, "SER", nullptr},
    {Op::Pack, "ASSEM", nullptr},
    {Op::Unpack, "DISAS", nullptr},
    {Op::RangeConvert, "ACVT", nullptr},
    {Op::PointToNumber, "PTN", nullptr},
    {Op::NumberToPoint, "NTP", nullptr},
    {Op::MCodeGet, "MGET", nullptr},
    {Op::MCodeAck, "MACK", nullptr},
    {Op::TCodeGet, "TGET", nullptr},
    {Op::TCodeAck, "TACK", nullptr},
    {Op::HandwheelPulse, "RTOMPG", nullptr},
    {Op::TempSensor, "TEMPSEN", nullptr},
    {Op::PartCount, "PARTCNT", nullptr},
    {Op::PartClear, "PARTCLR", nullptr},
    {Op::HeadSensors, "HEADSEN", nullptr},
    {Op::VarGet, "VARGET", nullptr},
    {Op::VarSet, "VARSET", nullptr},
    {Op::ToolVectorOn, "TOOLSET", nullptr},
    {Op::ToolVectorOff, "TOOLCLR", nullptr},
    {Op::PanelDisplay, "NIXIE", nullptr},
    {Op::ToolInUse, "TOOLUSE", nullptr},
    {Op::ToolLife, "TOOLLIFE", nullptr},
    {Op::ToolSelect, "TOOL", nullptr},
    {Op::SpindleAnalog, "SPDA", nullptr},
    {Op::SlaveHomingEnable, "SUBAXEN", nullptr},
    {Op::HandwheelSet, "MPGSET", nullptr},
    {Op::MagazineRotate, "ROT", nullptr},
    {Op::RaiseEvent, "EVENT", nullptr},
    {Op::SaveRetained, "SAVEDATA", nullptr},
    {Op::ChannelModeSet, "MDST", nullptr},
    {Op::ChannelModeGet, "MDGT", nullptr},
    {Op::MdiMode, "MDI", nullptr},
    {Op::MstLock, "MST", nullptr},
    {Op::CycleStart, "CYCLE", nullptr},
    {Op::EmergencyStop, "STOP", nullptr},
    {Op::ChannelReset, "RESET", nullptr},
    {Op::ChannelSwitch, "CHANSW", nullptr},
    {Op::FeedHold, "HOLD", nullptr},
    {Op::CycleStartLamp, "CYCLED", nullptr},
    {Op::FeedHoldLamp, "HOLDLED", nullptr},
    {Op::SkipG31, "ESCBLK", nullptr},
    {Op::RapidOverride, "RPOVRD", nullptr},
    {Op::FeedOverride, "FEEDOVRD", nullptr},
    {Op::SpindleOverride, "SPDLOVRD", nullptr},
    {Op::StepMultiplier, "STEPMUL", nullptr},
    {Op::DryRun, "DRYRUN", nullptr},
    {Op::BlockSkip, "SKIP", nullptr},
    {Op::UserInput, "USERIN", nullptr},
    {Op::UserOutput, "USEROUT", nullptr},
    {Op::OptionalStop, "SELSTOP", nullptr},
    {Op::SpindleJog, "SPDLJOG", nullptr},
    {Op::BusSpindle, "SPDLBUS", nullptr},
    {Op::BusSpindleGeared, "SPDLBUS1", nullptr},
    {Op::SpindleOrient, "SPDLORI", nullptr},
    {Op::SpindleOrientDone, "SPDLOROK", nullptr},
    {Op::SpindleZeroSpeed, "SPDLZERO", nullptr},
    {Op::SpindleSpeedReached, "SPDLRCH", nullptr},
    {Op::SlaveRelease, "DESYN", nullptr},
    {Op::AxisJog, "JOGSW", nullptr},
    {Op::AxisStep, "STEPAXIS", nullptr},
    {Op::JogSpeed, "JOGVEL", nullptr},
    {Op::HomingStart, "HOMRUN", nullptr},
    {Op::HomingStartDir, "HOMERUN1", nullptr},
    {Op::HomeDog, "HOMESW", nullptr},
    {Op::HomingDoneLamp, "HOMLED", nullptr},
    {Op::AxisEnable, "AXEN", nullptr},
    {Op::AxisReady, "AXRDY", nullptr},
    {Op::AxisLock, "AXISLOCK", nullptr},
    {Op::AxisMoveRelative, "AXISMOVE", nullptr},
    {Op::AxisMoveAbsolute, "AXISMVTO", nullptr},
    {Op::SecondSoftLimit, "AXLMF2", nullptr},
    {Op::PositiveLimitDog, "AXISPLMT", nullptr},
    {Op::NegativeLimitDog, "AXISNLMT", nullptr},
    {Op::ServoEnable, "SVSW", nullptr},
    {Op::AxisControlMode, "AXISMODE", nullptr},
    {Op::ReferencePoint, "REFPT", nullptr},
    {Op::AxisHoming, "AXISHOM2", nullptr},
    {Op::AxisMoving, "AXMOVING", nullptr},
    {Op::Alarm, "ALARM", nullptr},
    {Op::ResetRequested, "RSTCHK", nullptr},
    {Op::ResetClear, "RSTCLR", nullptr},
};

constexpr int kRowCount = static_cast<int>(sizeof(kRows) / sizeof(kRows[0]));

constexpr bool rowsInOrder() {
  for (int i = 1; i < kRowCount; ++i)
    if (static_cast<int>(kRows[i - 1].op) >= static_cast<int>(kRows[i].op)) return false;
  return true;
}
static_assert(rowsInOrder(), "rows are in Op order, one per spelled operation");

/// Row index of each operation, -1 where HNC-8 has no spelling.
struct RowIndex {
  int16_t at[kOpCount];
};
constexpr RowIndex buildRowIndex() {
  RowIndex x{};
  for (int i = 0; i < kOpCount; ++i) x.at[i] = -1;
  for (int i = 0; i < kRowCount; ++i) x.at[static_cast<int>(kRows[i].op)] = static_cast<int16_t>(i);
  return x;
}
constexpr RowIndex kRowIndex = buildRowIndex();

} // namespace

std::span<const MnemonicRow> mnemonicTable() { return {kRows, static_cast<size_t>(kRowCount)}; }

const MnemonicRow *mnemonicRow(Op op) {
  auto i = static_cast<int>(op);
  if (i < 0 || i >= kOpCount || kRowIndex.at[i] < 0) return nullptr;
  return &kRows[kRowIndex.at[i]];
}

namespace {

/// Every spelling and alias, upper case -> Op, built once. A spelling wins over an alias of the
/// same text (the order the linear search of before checked them in).
const std::unordered_map<std::string, Op> &mnemonicIndex() {
  static const std::unordered_map<std::string, Op> index = [] {
    std::unordered_map<std::string, Op> m;
    m.reserve(2 * kOpCount);
    for (const MnemonicRow &row : kRows) m.emplace(row.spelling, row.op);
    for (const MnemonicRow &row : kRows)
      if (row.alias) m.emplace(row.alias, row.op); // emplace keeps an existing spelling
    return m;
  }();
  return index;
}

} // namespace

bool lookupMnemonic(std::string_view m, Op &out) {
  // The parser asks once per statement: a hash lookup instead of comparing against every row
  // (which was half of parsing a 10,000-statement program, docs/BENCHMARKS.md "Tiering").
  std::string key(m);
  for (char &c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  const std::unordered_map<std::string, Op> &index = mnemonicIndex();
  auto it = index.find(key);
  if (it == index.end()) return false;
  out = it->second;
  return true;
}

namespace detail { // NetworkText.cpp
bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &error);
} // namespace detail

const DialectText &dialectText() {
  static constexpr DialectText kText{
      "hnc8",  &spellingOf,     &formatOperand,           nullptr,
      nullptr, &lookupMnemonic, &detail::printStatements, &symbolRules};
  return kText;
}

} // namespace lj::hnc8
