// plc.dit container: round trip, canonical form and hash, and one test per error class of
// docs/plc-dit.md "Errors". Expected texts come from that document.
#include "DitTestUtil.h"

#include "formats/InputFiles.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

using dittest::errorOf;
using dittest::smallBody;
using dittest::withHash;

// FIPS 180-2 appendix B.1 test vector: SHA-256("abc").
TEST(DitHash, KnownVector) {
  EXPECT_EQ(formats::sha256Hash("abc"),
            "sha256:ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
}

formats::DitFile sample() {
  formats::DitFile d;
  d.plc2Nvalue = 0;
  d.periodMs = 10;
  std::string err;
  // CRLF and a missing final newline in the STL are normalized (docs "Writing").
  EXPECT_TRUE(formats::normalizeProgram("; demo\r\nLD START\r\nOUT 主轴\nMOV 0x10 COUNT", "p.stl",
                                        d.program, err))
      << err;
  EXPECT_TRUE(d.symbols.add("START", "x0010.3", "  start key  ", err)) << err;
  EXPECT_TRUE(d.symbols.add("主轴", "Y0.0", "# not a marker here", err)) << err;
  EXPECT_TRUE(d.symbols.add("COUNT", "d5", "", err)) << err;
  std::optional<std::vector<formats::Assignment>> ps =
      formats::parseParams("P3=0x10\nP12 = -4\n", "p", err);
  EXPECT_TRUE(ps.has_value()) << err;
  if (ps) d.params = *ps;
  return d;
}

TEST(DitFormat, RoundTrip) {
  formats::DitFile d = sample();
  EXPECT_EQ(d.program, "; demo\nLD START\nOUT 主轴\nMOV 0x10 COUNT\n");
  std::string text = formats::writeDit(d);
  std::string err;
  std::optional<formats::DitFile> back = formats::parseDit(text, "r.dit", err);
  ASSERT_TRUE(back) << err << "\n" << text;
  EXPECT_EQ(back->program, d.program);
  EXPECT_EQ(back->plc2Nvalue, 0);
  EXPECT_EQ(back->periodMs, 10u);
  ASSERT_EQ(back->params.size(), 2u);
  EXPECT_EQ(back->params[0].addr.index, 3);
  EXPECT_EQ(back->params[0].value, 16);
  EXPECT_EQ(back->params[1].addr.index, 12);
  EXPECT_EQ(back->params[1].value, -4);
  ASSERT_EQ(back->symbols.size(), 3u);
  const std::vector<Symbol> &s = back->symbols.symbols();
  EXPECT_EQ(s[0].name, "START");
  EXPECT_EQ(s[0].address, "X10.3"); // normalized (docs "Symbols": address)
  EXPECT_EQ(s[0].comment, "start key");
  EXPECT_EQ(s[1].name, "主轴");
  EXPECT_EQ(s[1].comment, "# not a marker here"); // the writer's own " # " marker is dropped
  EXPECT_EQ(s[2].address, "D5");
  EXPECT_EQ(s[2].comment, "");
  EXPECT_EQ(back->hash, formats::sha256Hash(formats::ditCanonical(d)));
  // The program starts after 13 lines: magic, hash, comment, [params] + 4, [symbols] + 3 and
  // [program].
  EXPECT_EQ(back->programLine, 14);
  // Writing what was read gives the same bytes.
  EXPECT_EQ(formats::writeDit(*back), text);
}

TEST(DitFormat, CanonicalSerialization) {
  formats::DitFile d = sample();
  EXPECT_EQ(formats::ditCanonical(d), "ladderjit-plc-dit 1\n"
                                      "[params]\n"
                                      "plc2_nvalue = 0\n"
                                      "period_ms = 10\n"
                                      "P3 = 16\n"
                                      "P12 = -4\n"
                                      "[symbols]\n"
                                      "START X10.3 # start key\n"
                                      "主轴 Y0.0 # # not a marker here\n"
                                      "COUNT D5\n"
                                      "[program]\n"
                                      "; demo\n"
                                      "LD START\n"
                                      "OUT 主轴\n"
                                      "MOV 0x10 COUNT\n"
                                      "[end]\n");
}

// docs "Layout": comments, blank lines, CRLF, blanks around '=' and hex spelling are not content.
TEST(DitFormat, LayoutDoesNotChangeTheHash) {
  std::string text = withHash(smallBody());
  ASSERT_EQ(errorOf(text), "");
  std::string edited = text;
  edited.replace(edited.find("[params]\n"), 9, "\n# my comment\n[params]\n\n");
  edited.replace(edited.find("P12 = 345"), 9, "P12=0x159");
  edited.replace(edited.find("START X1.0 # start key"), 22, "  START   x1.0   ;  start key  ");
  edited += "\n# trailing comment\n";
  EXPECT_EQ(errorOf(edited), "");
  std::string crlf;
  for (char c : text) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  EXPECT_EQ(errorOf(crlf), "");
  EXPECT_EQ(errorOf("\xEF\xBB\xBF" + text), "");
}

TEST(DitFormat, ProgramIsVerbatim) {
  // Leading blanks, `#` and `[` after a blank are program text, not comments or headers.
  std::string body = "ladderjit-plc-dit 1\n[params]\nplc2_nvalue = 1\nperiod_ms = 1\n[symbols]\n"
                     "[program]\n# not a comment\n  [not a header]\n\n[end]\n";
  std::string err;
  std::optional<formats::DitFile> d = formats::parseDit(withHash(body), "v.dit", err);
  ASSERT_TRUE(d) << err;
  EXPECT_EQ(d->program, "# not a comment\n  [not a header]\n\n");
}

TEST(DitFormat, NormalizeRejectsBracketLines) {
  std::string out, err;
  EXPECT_FALSE(formats::normalizeProgram("LD X1.0\n[end]\nOUT Y0.0\n", "p.stl", out, err));
  EXPECT_EQ(err.rfind("p.stl:2: a line starting with '['", 0), 0u) << err;
}

TEST(DitFormat, ProgramForParserKeepsContainerLines) {
  std::string err;
  std::optional<formats::DitFile> d = formats::parseDit(withHash(smallBody()), "s.dit", err);
  ASSERT_TRUE(d) << err;
  // Magic, hash, [params] + 3, [symbols] + 2, [program]: the program starts on line 11.
  EXPECT_EQ(d->programLine, 11);
  EXPECT_EQ(formats::programForParser(*d),
            std::string(10, '\n') + "LD START\nOUT Y0.0\nMOV 7 COUNT\n");
}

// ---- one test per error class (docs "Errors") ----

void expectError(const std::string &text, const std::string &prefix, const std::string &part) {
  std::string e = errorOf(text);
  EXPECT_EQ(e.rfind(prefix, 0), 0u) << "expected prefix '" << prefix << "' in: " << e;
  EXPECT_NE(e.find(part), std::string::npos) << "expected '" << part << "' in: " << e;
}

std::string replaced(std::string s, const std::string &from, const std::string &to) {
  size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

TEST(DitErrors, EmptyAndMagic) {
  expectError("", "t.dit:1: ", "empty file");
  expectError(replaced(withHash(smallBody()), "ladderjit-plc-dit", "ladderjit-plc-dot"),
              "t.dit:1: ", "wrong magic 'ladderjit-plc-dot'");
  expectError("LD X1.0\nOUT Y0.0\n", "t.dit:1: ", "not a ladderjit plc.dit container");
}

TEST(DitErrors, Version) {
  expectError(replaced(withHash(smallBody()), "ladderjit-plc-dit 1", "ladderjit-plc-dit 2"),
              "t.dit:1: ", "unsupported plc.dit version 2 (this ladderjit reads version 1)");
  expectError(replaced(withHash(smallBody()), "ladderjit-plc-dit 1", "ladderjit-plc-dit"),
              "t.dit:1: ", "bad version");
}

TEST(DitErrors, HashLine) {
  std::string t = withHash(smallBody());
  expectError(replaced(t, "hash = sha256:", "hash = md5:"), "t.dit:2: ", "bad hash line");
  size_t at = t.find("sha256:") + 7;
  expectError(t.substr(0, at + 10) + t.substr(at + 64), "t.dit:2: ", "64 hex digits");
}

TEST(DitErrors, Sections) {
  std::string t = withHash(smallBody());
  expectError(replaced(t, "[symbols]\nSTART X1.0 # start key\nCOUNT D5\n", ""),
              "t.dit:7: ", "missing section [symbols] before [program]");
  expectError(replaced(t, "[params]\n", ""), "t.dit:3: ", "text outside a section");
  expectError(replaced(t, "COUNT D5\n", "COUNT D5\n[params]\n"),
              "t.dit:10: ", "duplicate section [params]");
  expectError(replaced(t, "[symbols]", "[symbol]"),
              "t.dit:7: ", "unknown section header '[symbol]'");
  expectError(t + "LD X1.0\n", "t.dit:15: ", "text after [end]: 'LD X1.0'");
  expectError(replaced(t, "period_ms = 10\n", ""),
              "t.dit:6: ", "missing parameter period_ms in [params]");
}

TEST(DitErrors, Truncated) {
  std::string t = withHash(smallBody());
  expectError(t.substr(0, t.find("[end]")),
              "t.dit:13: ", "truncated file: it ends inside [program], before the [end] line");
  // Cut inside the [end] header: the last line has no newline, the message says so.
  expectError(t.substr(0, t.size() - 3), "t.dit:14: ", "without a newline: truncated?");
  // Only the final newline missing: the content is complete, the file is fine.
  EXPECT_EQ(errorOf(t.substr(0, t.size() - 1)), "");
}

TEST(DitErrors, Symbols) {
  std::string t = smallBody();
  expectError(withHash(replaced(t, "COUNT D5", "X10 D5")), "t.dit:9: ", "bad symbol name 'X10'");
  expectError(withHash(replaced(t, "COUNT D5", "1COUNT D5")), "t.dit:9: ", "bad symbol name");
  expectError(withHash(replaced(t, "COUNT D5", "CO-UNT D5")), "t.dit:9: ", "bad symbol name");
  expectError(withHash(replaced(t, "COUNT D5", "COUNT Q5")),
              "t.dit:9: ", "symbol 'COUNT': bad address 'Q5'");
  expectError(withHash(replaced(t, "COUNT D5", "COUNT D5.32")), "t.dit:9: ", "bit number");
  expectError(withHash(replaced(t, "COUNT D5", "COUNT X600.0")), "t.dit:9: ", "out of range");
  expectError(withHash(replaced(t, "COUNT D5", "COUNT L3.1")), "t.dit:9: ", "bit number");
  expectError(withHash(replaced(t, "COUNT D5", "COUNT")), "t.dit:9: ", "has no address");
  expectError(withHash(replaced(t, "COUNT D5", "start D5")), "t.dit:9: ",
              "duplicate symbol 'start' (already defined as 'START'; names are case-insensitive)");
}

std::string withSymbols(int n) {
  std::string body = "ladderjit-plc-dit 1\n[params]\nplc2_nvalue = 200\nperiod_ms = 1\n[symbols]\n";
  for (int i = 0; i < n; ++i) body += "S_" + std::to_string(i) + " D0\n";
  return withHash(body + "[program]\nLD X0.0\n[end]\n");
}

// HNC-8 specification: "symbol names 1000 entries".
TEST(DitErrors, AtMostThousandSymbols) {
  EXPECT_EQ(errorOf(withSymbols(1000)), "");
  // Symbol 1001 is on line 2 (hash) + 4 + 1001 = 1007.
  expectError(withSymbols(1001), "t.dit:1007: ", "too many symbols: at most 1000");
}

TEST(DitErrors, Params) {
  std::string t = smallBody();
  expectError(withHash(replaced(t, "P12 = 345", "P200 = 1")), "t.dit:6: ", "bad parameter");
  expectError(withHash(replaced(t, "P12 = 345", "P12.0 = 1")), "t.dit:6: ", "bad parameter");
  expectError(withHash(replaced(t, "P12 = 345", "P12 = 345\nP12 = 1")),
              "t.dit:7: ", "duplicate parameter P12");
  expectError(withHash(replaced(t, "plc2_nvalue = 50", "plc2_nvalue = -1")),
              "t.dit:4: ", "bad parameter plc2_nvalue");
  expectError(withHash(replaced(t, "period_ms = 10", "period_ms = 0")),
              "t.dit:5: ", "bad parameter period_ms");
  expectError(withHash(replaced(t, "period_ms = 10", "period_ms = 10\nperiod_ms = 5")),
              "t.dit:6: ", "duplicate parameter period_ms");
  expectError(withHash(replaced(t, "P12 = 345", "speed = 3")),
              "t.dit:6: ", "unknown parameter 'speed'");
  expectError(withHash(replaced(t, "P12 = 345", "P12 345")), "t.dit:6: ", "expected NAME = VALUE");
}

TEST(DitErrors, HashMismatchOnProgramEdit) {
  std::string t = withHash(smallBody());
  expectError(replaced(t, "OUT Y0.0", "OUT Y0.1"),
              "t.dit:2: ", "content hash does not match: file was modified or truncated");
  expectError(replaced(t, "P12 = 345", "P12 = 346"), "t.dit:2: ", "content hash does not match");
  expectError(replaced(t, "# start key", "# stop key"), "t.dit:2: ", "content hash does not match");
}

} // namespace
} // namespace lj
