// Composition of lj_host tables: a layer over whatever host is bound (e.g. the retentive store
// over the simulated NC), without globals. Every callback reaches the base host unchanged.
#pragma once

#include "ladderjit/abi.h"

#include <functional>

namespace lj::hosts {

/// An lj_host that forwards every callback to the host bound before it (its base, which may be
/// null) and, after the base's save_data, calls `onSaveData`. A member the base leaves null stays
/// null here (the engines' "no NC service" behaviour), except save_data, which the layer serves.
/// The chain's own address is the table's ctx, so it must not move while bound.
class HostChain {
public:
  explicit HostChain(std::function<void()> onSaveData) : onSaveData_(std::move(onSaveData)) {}
  HostChain(const HostChain &) = delete;
  HostChain &operator=(const HostChain &) = delete;

  /// Layer over `s.host` unless this chain is already bound there. Call before every tick: a
  /// binding that installs its own table (the simulated NC at power-up) is then wrapped anew.
  void bindOver(lj_state &s);

  /// The host this chain forwards to (null: none).
  const lj_host *base() const { return base_; }

private:
  struct Calls; ///< the trampolines (hosts/HostChain.cpp)
  const lj_host *base_ = nullptr;
  lj_host table_{};
  std::function<void()> onSaveData_;
};

} // namespace lj::hosts
