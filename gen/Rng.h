// A small seeded PRNG (splitmix64) whose sequences are identical on every platform, so a fuzz
// seed or a benchmark program reproduces exactly (std::*_distribution is implementation-defined).
#pragma once

#include <cstdint>
#include <span>

namespace lj::gen {

/// Deterministic 64-bit generator with the helpers the generators need.
class Rng {
public:
  explicit Rng(uint64_t seed) : s_(seed ^ 0x9E3779B97F4A7C15ull) {}

  /// Next raw 64-bit value (splitmix64).
  uint64_t next() {
    uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, n) for n > 0 (the tiny modulo bias does not matter here).
  uint64_t below(uint64_t n) { return n ? next() % n : 0; }

  /// Uniform in [lo, hi], inclusive.
  int64_t range(int64_t lo, int64_t hi) {
    return lo + static_cast<int64_t>(below(static_cast<uint64_t>(hi - lo) + 1));
  }

  /// True with probability `percent` / 100.
  bool chance(int percent) { return static_cast<int>(below(100)) < percent; }

  /// One element of a non-empty span.
  template <typename T> const T &pick(std::span<const T> v) { return v[below(v.size())]; }

  /// Index chosen with the given relative weights (at least one positive).
  int weighted(std::span<const int> w) {
    int total = 0;
    for (int x : w) total += x;
    int r = static_cast<int>(below(static_cast<uint64_t>(total)));
    for (size_t i = 0; i < w.size(); ++i) {
      if (r < w[i]) return static_cast<int>(i);
      r -= w[i];
    }
    return static_cast<int>(w.size()) - 1;
  }

  /// A derived seed, so sub-generators do not share a sequence.
  uint64_t fork() { return next() ^ 0xD1B54A32D192ED03ull; }

private:
  uint64_t s_;
};

} // namespace lj::gen
