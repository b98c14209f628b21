// The operand draws shared by the FANUC functional-instruction rung generators
// (gen/FanucData.cpp, gen/FanucArith.cpp): one random source and one output, the same pools.
#pragma once

#include "gen/Rng.h"

#include <string>
#include <utility>
#include <vector>

namespace lj::gen {

class FanucRungBase {
protected:
  FanucRungBase(Rng &r, std::vector<std::string> &out) : r_(r), out_(out) {}

  int64_t pick(int64_t lo, int64_t hi) { return r_.range(lo, hi); }
  void line(std::string s) { out_.push_back(std::move(s)); }
  /// A data length 1, 2 or 4.
  int width() {
    static constexpr int kW[] = {1, 2, 4};
    return kW[pick(0, 2)];
  }
  /// A bit to read: an input, a system relay R9091.0/.1 or a writable bit.
  std::string readBit() {
    switch (pick(0, 4)) {
    case 0:
    case 1: {
      const std::string area = r_.chance(70) ? "X" : "F";
      return area + std::to_string(pick(0, 3)) + "." + std::to_string(pick(0, 7));
    }
    case 2:
      return "R9091." + std::to_string(pick(0, 1));
    default:
      return writeBit();
    }
  }
  /// A writable bit of the R and D pools.
  std::string writeBit() {
    return std::string(r_.chance(60) ? "R" : "D") + std::to_string(pick(0, 7)) + "." +
           std::to_string(pick(0, 7));
  }

  Rng &r_;
  std::vector<std::string> &out_;
};

} // namespace lj::gen
