// Bad input never crashes the ClassicLadder reader: random bytes, and deterministic mutations
// (byte flips, inserted format characters, deleted and repeated lines, truncation) of a small
// project and, when ../shared is there, of every real .clp/.clprj. Each project that still
// reads has its expressions evaluated, so the evaluator sees mutated trees too.
#include "frontends/classicladder/Reader.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <random>
#include <sstream>

using namespace lj::classicladder;

namespace {

const char *kSeed =
    "_FILES_CLASSICLADDER\n_FILE-sections.csv\n#VER=1.0\n#NAME000=Prog1\n000,0,-1,0,1,0\n"
    "_/FILE-sections.csv\n_FILE-arithmetic_expressions.csv\n#VER=2.0\n0000,@270/0@>5\n"
    "0001,@280/0@:=(@270/0@*2)^1%3\n_/FILE-arithmetic_expressions.csv\n_FILE-rung_0.csv\n"
    "#VER=2.0\n#NEXTRUNG=1\n1-0-50/0 , 99-0-0/0 , 20-0-0/0 , 9-0-0/0 , 99-0-0/0 , 13-0-0/0 , "
    "9-0-0/0 , 99-0-0/0 , 99-0-0/0 , 60-0-0/1\n0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , "
    "99-1-0/0 , 99-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 50-1-60/0\n_/FILE-rung_0.csv\n"
    "_FILE-rung_1.csv\n#VER=2.0\n#NEXTRUNG=-1\n3-0-0/1 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , "
    "9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 54-0-0/0\n_/FILE-rung_1.csv\n"
    "_FILE-sequential.csv\n#VER=1.0\nS0,1,0,0,1,1\nS1,0,1,0,1,5\nT0,1,-1,-1,-1,-1,-1,-1,-1,-1,"
    "-1,0,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,-1,"
    "-1,0,1,3\nC0,0,0/1\n_/FILE-sequential.csv\n_FILE-timers_iec.csv\n1,5,0\n"
    "_/FILE-timers_iec.csv\n_/FILES_CLASSICLADDER\n";

std::string mutate(std::string s, std::mt19937_64 &rng) {
  static const char alphabet[] = "0123456789-/,@[]#_\n%=:<>()^$!ABSMINIXFILE- \r";
  int rounds = 1 + static_cast<int>(rng() % 4);
  for (int k = 0; k < rounds && !s.empty(); ++k) {
    size_t at = rng() % s.size();
    switch (rng() % 7) {
    case 0:
      s[at] = static_cast<char>(rng());
      break;
    case 1:
      s.insert(at, 1, alphabet[rng() % (sizeof alphabet - 1)]);
      break;
    case 2:
      s.erase(at, 1 + rng() % 16);
      break;
    case 3: { // repeat a line
      size_t b = s.rfind('\n', at), e = s.find('\n', at);
      b = b == std::string::npos ? 0 : b + 1;
      if (e != std::string::npos) s.insert(b, s.substr(b, e - b + 1));
      break;
    }
    case 4:
      s.resize(at);
      break;
    case 5:
      s[at] = alphabet[rng() % (sizeof alphabet - 1)];
      break;
    case 6: { // a digit becomes a large or negative number
      if (s[at] >= '0' && s[at] <= '9') s.replace(at, 1, rng() % 2 ? "99999999" : "-1");
      break;
    }
    }
  }
  return s;
}

int32_t anyValue(const VarRef &v) { return v.type * 31 + v.num; }

/// Reads `text`; on success walks the model and evaluates every expression.
void exercise(const std::string &text, const std::string &name) {
  auto r = readProjectText(text, name);
  if (!r.ok()) {
    EXPECT_FALSE(r.status().message().empty());
    return;
  }
  for (const auto &[i, a] : r->expressions) {
    (void)i;
    if (a.expr.isCompare) (void)evaluateCompare(a.expr, anyValue);
    if (a.expr.isOperate) (void)evaluate(*a.expr.value, anyValue);
  }
  for (const auto &s : r->sections)
    for (int32_t n : s.order) EXPECT_TRUE(r->rungs.count(n));
}

} // namespace

TEST(ClRobustness, SeedReads) {
  auto r = readProjectText(kSeed, "seed.clp");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->sections[0].order, (std::vector<int32_t>{0, 1}));
}

TEST(ClRobustness, RandomBytes) {
  std::mt19937_64 rng(31);
  for (int i = 0; i < 3000; ++i) {
    std::string s(rng() % 600, '\0');
    for (auto &c : s) c = static_cast<char>(rng());
    if (i % 2) s = "_FILES_CLASSICLADDER\n_FILE-rung_0.csv\n" + s;
    exercise(s, i % 3 ? "r.clp" : "r.clprj");
  }
}

TEST(ClRobustness, MutatedSeed) {
  std::mt19937_64 rng(3131);
  int read = 0;
  for (int i = 0; i < 20000; ++i) {
    std::string m = mutate(kSeed, rng);
    read += readProjectText(m, "m.clp").ok();
    exercise(m, "m.clp");
  }
  EXPECT_GT(read, 0); // some mutations keep a valid project
}

#ifdef LJ_CL_REAL_DIR
TEST(ClRobustness, MutatedRealProjects) {
  std::mt19937_64 rng(31031);
  int files = 0;
  for (const auto &e : std::filesystem::recursive_directory_iterator(LJ_CL_REAL_DIR)) {
    std::string ext = e.path().extension().string();
    if (ext != ".clp" && ext != ".clprj") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    ++files;
    for (int i = 0; i < 300; ++i) exercise(mutate(ss.str(), rng), "x" + ext);
  }
  EXPECT_EQ(files, 63);
}
#endif
