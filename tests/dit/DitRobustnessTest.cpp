// plc.dit reader robustness: every single-byte flip in the program section is a hash mismatch,
// every truncation is a clean located error, and random bytes or random mutations of a valid
// container never crash (fixed seeds, so failures reproduce).
#include "DitTestUtil.h"

#include <gtest/gtest.h>

#include <random>

namespace lj {
namespace {

using dittest::errorOf;
using dittest::smallBody;
using dittest::withHash;

TEST(DitRobustness, EveryProgramByteFlipIsDetected) {
  std::string t = withHash(smallBody());
  size_t begin = t.find("[program]\n") + 10, end = t.find("[end]");
  for (size_t i = begin; i < end; ++i) {
    std::string bad = t;
    bad[i] = static_cast<char>(bad[i] ^ 0x01);
    std::string e = errorOf(bad);
    if (i + 1 == end) // the program's last newline glues the [end] line to the program
      EXPECT_NE(e.find("truncated file"), std::string::npos) << i << ": " << e;
    else
      EXPECT_NE(e.find("t.dit:2: content hash does not match: file was modified or truncated"),
                std::string::npos)
          << i << ": " << e;
  }
}

TEST(DitRobustness, EveryTruncationIsAnError) {
  std::string t = withHash(smallBody());
  // Only the final newline may go (docs "Errors"): every shorter prefix is rejected with
  // `t.dit:LINE: `.
  for (size_t n = 0; n + 1 < t.size(); ++n) {
    std::string e = errorOf(t.substr(0, n));
    EXPECT_EQ(e.rfind("t.dit:", 0), 0u) << n << ": " << e;
  }
}

// The error, if any, is one located line; the test would crash or hang on a reader bug.
void expectClean(const std::string &text) {
  std::string e = errorOf(text);
  if (e.empty()) return;
  EXPECT_EQ(e.rfind("t.dit:", 0), 0u) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << e;
}

TEST(DitRobustness, RandomBytes) {
  std::mt19937 rng(20240611);
  std::uniform_int_distribution<int> byte(0, 255), len(0, 400);
  for (int i = 0; i < 2000; ++i) {
    std::string s(static_cast<size_t>(len(rng)), '\0');
    for (char &c : s) c = static_cast<char>(byte(rng));
    // Half of them start like a container so the section parser is reached too.
    if (i % 2) s = "ladderjit-plc-dit 1\nhash = sha256:" + std::string(64, 'a') + "\n" + s;
    expectClean(s);
  }
}

TEST(DitRobustness, RandomMutations) {
  std::mt19937 rng(7);
  std::string t = withHash(smallBody());
  const std::string alphabet = "[]=#;\n\r \tXYDP0159._aZ\xE4\xB8\xBB";
  for (int i = 0; i < 3000; ++i) {
    std::string s = t;
    int edits = 1 + static_cast<int>(rng() % 4);
    for (int k = 0; k < edits && !s.empty(); ++k) {
      size_t at = rng() % s.size();
      char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 3) {
      case 0:
        s[at] = c;
        break;
      case 1:
        s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), c);
        break;
      default:
        s.erase(at, 1 + rng() % 8);
        break;
      }
    }
    expectClean(s);
  }
}

} // namespace
} // namespace lj
