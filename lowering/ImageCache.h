// Keeps state fields in SSA registers within one basic block: the first read loads, later reads
// reuse the value, and each write stores at once but deletes the previous store of the same
// field in the block (nothing can have read it: every read in the block is served from here).
// So a rung that writes three bits of Y0 stores Y0 once, at its last write, which keeps live
// ranges short (no pile of deferred stores at the end of a long block).
#pragma once

#include "lowering/AbiTypes.h"

#include <llvm/IR/IRBuilder.h>

#include <map>

namespace lj::lower {

/// Per-basic-block cache of lj_state fields, keyed by byte offset. Every field outside the byte
/// region is always accessed with the same type (one StateLoc per offset), so those entries never
/// overlap; byte-region locations (StateLoc::span > 0: R100 as a byte, R100..R101 as a word) may,
/// and an access drops every other entry it overlaps.
class ImageCache {
public:
  ImageCache(const StateLayout &layout, llvm::IRBuilderBase &b, llvm::Value *state)
      : layout_(layout), b_(b), state_(state) {}

  /// Current value of `loc` (loaded on first use in this block).
  llvm::Value *load(const StateLoc &loc);
  /// New value of `loc`: stored here, replacing this block's earlier store of `loc`.
  void store(const StateLoc &loc, llvm::Value *v);
  /// Forget all cached values (every write is already stored). Call before a terminator, a call,
  /// or anything else that ends the straight-line region.
  void flush();

private:
  void dropOverlaps(const StateLoc &loc);
  struct Entry {
    StateLoc loc;
    llvm::Value *value;
    llvm::Value *addr;          ///< GEP of the first access, reused by later ones
    llvm::StoreInst *lastStore; ///< this block's store of the field, if any
  };
  const StateLayout &layout_;
  llvm::IRBuilderBase &b_;
  llvm::Value *state_;
  std::map<uint32_t, Entry> entries_;
};

} // namespace lj::lower
