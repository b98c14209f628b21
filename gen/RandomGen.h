// Internal to the random program generator (gen/RandomProgram.cpp, gen/RandomOperands.cpp):
// the generator class and the long-range constants both halves use.
#pragma once

#include "gen/ProgramGenerator.h"
#include "gen/Rng.h"
#include "ir/OpTable.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace lj::gen::detail {

/// Share (percent) of BMOV / FMOV / ZRST / COD / SER statements given a range of 33..100
/// elements: only ranges longer than the lowering's unroll limit (32, lowering/EmitData.cpp)
/// become LLVM loops (or, for COD, a computed address), so these fuzz the loop code.
constexpr int kLongPercent = 10;

/// Rows that take a long range, and the share (per mille) of generic statements that are one of
/// them in long form on top of kLongPercent: a long BMOV overlapping the hot registers in the
/// wrong direction shows only when it runs with EN = 1 on varied values, so the campaign needs
/// a few hundred of them, more than 10% of a row among ~145 gives (item 2 of the fuzz2 brief).
constexpr Op kLongRows[] = {Op::BlockMove, Op::BlockMove,   Op::BlockMove,  Op::Fill,
                            Op::ZoneReset, Op::TableSearch, Op::TableLookup};
constexpr int kLongPerMille = 12;

/// Per-program mix of stack behaviour: deep block nesting, or flat rungs with dead entries
/// (which give the slice planner rung boundaries).
struct Profile {
  std::array<int, 9> weight; ///< indexed by StackRule
  int32_t depthCap;
};

/// The random program generator: structural planner and generic emission in
/// RandomProgram.cpp, operand choice in RandomOperands.cpp.
class RandomGen {
public:
  explicit RandomGen(const RandomOptions &o);

  GenProgram run();
  GenProgram snippet(Op op);

private:
  void emit(std::string s) {
    // Case-insensitive mnemonics (DIALECT.md 2): now and then exercise the lexer with lower case.
    if (rng_.chance(2))
      for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    lines_.push_back(std::move(s));
  }
  int32_t size() const { return static_cast<int32_t>(lines_.size()); }

  bool eligible(const InstrInfo &in) const;
  void emitGeneric(const InstrInfo &in);
  void emitOneGeneric();
  void emitPush();
  std::string operand(const InstrInfo &in, int i);
  std::string regAddress(AreaMask mask, bool writes);
  std::string bitAddress(AreaMask mask, bool writes);
  int32_t constFor(const InstrInfo &in, int i);
  int32_t tcFor(const InstrInfo &in);
  // Constraints the OperandSpecs cannot express (RandomSpecial section below).
  bool specialOperands(const InstrInfo &in, std::string &s);
  std::string range(AreaMask mask, bool writes, int32_t n);
  Area pickFitting(AreaMask mask, bool writes, int32_t n);
  int32_t longCount(int32_t limit);
  std::string longBmov(const InstrInfo &in);
  std::string longZone(bool bits);
  std::string zone();
  std::string indirect(const InstrInfo &in, int i);
  std::string checkedRegister(const InstrInfo &in, int i);
  Area pickArea(AreaMask mask);
  void closeMs();
  void resetStacks() { depth_ = ms_ = 0; }
  bool longRange() { return forceLong_ || rng_.chance(kLongPercent); }

  void block(int32_t budget, int nest);
  void forwardJump(int32_t budget, int nest);
  void backwardJump(int32_t budget, int nest);
  void loop(int32_t budget, int nest);
  void call();
  void retn();

  RandomOptions o_;
  Rng rng_;
  Profile prof_{};
  std::array<std::vector<const InstrInfo *>, 9> generic_;
  std::vector<const InstrInfo *> multi_; ///< blocks with more than one input
  std::vector<std::string> lines_;
  int32_t depth_ = 0, ms_ = 0;
  bool forceLong_ = false; ///< the statement being emitted takes a long range
  int32_t nextLabel_ = 0;
  int32_t nextGuard_ = 0;
  std::vector<int32_t> subNumbers_;  ///< subroutine i may call only j > i (no recursion)
  int32_t curSub_ = -1;              ///< -1 in the main parts
  std::map<int32_t, Op> tcOwner_[2]; ///< timer / counter number -> the one kind using it
};

} // namespace lj::gen::detail
