// The runtime ABI (runtime_abi/include/ladderjit/abi.h) seen from LLVM: the lj_state struct type
// and the location of every field the lowering touches (STYLE.md 6).
#pragma once

#include "ir/Area.h"

#include <llvm/ADT/SmallVector.h>
#include <llvm/IR/DataLayout.h>
#include <llvm/IR/DerivedTypes.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/Support/Error.h>

#include <cstdint>
#include <string>

namespace lj::lower {

/// One scalar field of lj_state: its byte offset (the identity used by the image cache), its
/// LLVM type and the struct-GEP path that reaches it.
struct StateLoc {
  uint32_t offset = 0;
  llvm::Type *type = nullptr;
  llvm::SmallVector<uint32_t, 4> path; ///< indices after the leading 0
  std::string name;                    ///< readable IR name ("X1", "T3.out", "edge7")
  uint8_t align = 0; ///< access alignment in bytes; 0 = the type's own (lj_state.mem: 1)
  /// Bytes the access covers (0: a field of its own type that no other StateLoc overlaps).
  uint8_t span = 0;
};

/// Fields of lj_timer / lj_counter, in struct order.
enum class TimerField : uint8_t { Start, Elapsed, Out, Running };
enum class CounterField : uint8_t { Value, Out, Prev };
/// The per-block byte arrays of PLS / PLF / ALT.
enum class BlockArray : uint8_t { PlsPrev, PlfPrev, AltPrev, AltState };
/// The scalar bookkeeping fields at the end of lj_state (Host: the `const lj_host *`).
enum class Scalar : uint8_t { NowMs, MaxSteps, Steps, FaultDivzero, FaultIndex, Host };

/// The lj_state type of one LLVMContext, built from the ABI header's layout and checked against
/// it (offsetof) with the target's DataLayout.
class StateLayout {
public:
  /// Builds the types; fails when the DataLayout places any field away from abi.h's offset.
  /// `names`: give StateLocs readable names (IR dumps); off for the JIT (saves compile time).
  static llvm::Expected<StateLayout> create(llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
                                            bool names = true);

  /// The `%lj_state` struct type.
  llvm::StructType *stateType() const { return state_; }
  /// sizeof(lj_state), for dereferenceable().
  static uint64_t stateSize();

  /// Element `index` of a numeric area (X Y F G R W D B P).
  StateLoc area(Area a, int32_t index) const;
  StateLoc timer(int32_t slot, TimerField f) const;
  StateLoc counter(int32_t slot, CounterField f) const;
  StateLoc block(BlockArray a, int32_t index) const;
  StateLoc edge(int32_t slot) const;
  /// `width` bytes (1, 2, 4, 8) at byte `offset` of lj_state inside the byte region mem (ABI v3),
  /// little-endian, alignment 1; such locations may overlap one another (ImageCache copes).
  StateLoc memBytes(uint32_t offset, unsigned width, std::string name = {}) const;
  /// Whether byte `offset` lies in lj_state.mem.
  static bool inMem(uint32_t offset);
  /// Per-instance word `slot` (lj_state.inst_word).
  StateLoc instWord(int32_t slot) const;
  StateLoc scalar(Scalar s) const;

  /// Address of `loc` inside the state pointed to by `state`.
  llvm::Value *address(llvm::IRBuilderBase &b, llvm::Value *state, const StateLoc &loc) const;

private:
  llvm::LLVMContext *ctx_ = nullptr;
  llvm::StructType *state_ = nullptr;
  bool names_ = true;
};

} // namespace lj::lower
