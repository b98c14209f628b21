// ControlSocket::answer and io::dumpJson / isUtf8: every answer is one valid JSON line, whatever
// the request bytes, the handler or the strings in the result (issue 11 finding 3).
#include "runtime/ControlSocket.h"
#include "io/StateJson.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <stdexcept>
#include <string>

namespace {

using lj::rt::ControlSocket;
using nlohmann::json;

json parsed(const std::string &line) {
  EXPECT_FALSE(line.empty());
  EXPECT_EQ(line.back(), '\n');
  EXPECT_EQ(line.find('\n'), line.size() - 1);
  return json::parse(line); // throws (fails the test) when not valid JSON / UTF-8
}

TEST(ControlAnswer, NonUtf8StringsInTheResultBecomeReplacementCharacters) {
  ControlSocket::Handler h = [](const json &) {
    return json{{"ok", false}, {"error", std::string("prog\xff\xfe.stl:1:1: error")}};
  };
  json j = parsed(ControlSocket::answer(h, R"({"cmd":"stats"})"));
  EXPECT_EQ(j["error"], "prog\xEF\xBF\xBD\xEF\xBF\xBD.stl:1:1: error"); // U+FFFD twice
}

TEST(ControlAnswer, HandlerExceptionsAndBadLinesAreErrorAnswers) {
  ControlSocket::Handler thrower = [](const json &) -> json { throw std::runtime_error("boom"); };
  json j = parsed(ControlSocket::answer(thrower, R"({"cmd":"read"})"));
  EXPECT_EQ(j["ok"], false);
  EXPECT_NE(j["error"].get<std::string>().find("boom"), std::string::npos);
  ControlSocket::Handler ints = [](const json &) -> json { throw 7; };
  EXPECT_EQ(parsed(ControlSocket::answer(ints, "{}"))["ok"], false);
  ControlSocket::Handler never = [](const json &) -> json {
    ADD_FAILURE() << "a malformed line reached the handler";
    return {};
  };
  for (std::string line : {std::string("\xff\xfe"), std::string("[1]"), std::string("{\"a\":"),
                           std::string("{\"cmd\":\"\xc0\xaf\"}"), std::string(100000, '[')})
    EXPECT_EQ(parsed(ControlSocket::answer(never, line))["error"], "request is not a JSON object")
        << line.substr(0, 20);
}

TEST(Utf8, WellFormedOnly) {
  EXPECT_TRUE(lj::io::isUtf8(""));
  EXPECT_TRUE(lj::io::isUtf8("plain ascii"));
  EXPECT_TRUE(lj::io::isUtf8("\xE4\xB8\xBB\xE8\xBD\xB4"));         // 主轴
  EXPECT_TRUE(lj::io::isUtf8("\xF0\x9F\x94\xA7"));                 // U+1F527
  EXPECT_TRUE(lj::io::isUtf8("\xF4\x8F\xBF\xBF"));                 // U+10FFFF
  EXPECT_FALSE(lj::io::isUtf8("\xff"));                            // never in UTF-8
  EXPECT_FALSE(lj::io::isUtf8("\xC0\xAF"));                        // overlong '/'
  EXPECT_FALSE(lj::io::isUtf8("\xE0\x80\xAF"));                    // overlong, 3 bytes
  EXPECT_FALSE(lj::io::isUtf8("\xED\xA0\x80"));                    // surrogate U+D800
  EXPECT_FALSE(lj::io::isUtf8("\xF4\x90\x80\x80"));                // above U+10FFFF
  EXPECT_FALSE(lj::io::isUtf8("\xE4\xB8"));                        // truncated
  EXPECT_FALSE(lj::io::isUtf8("a\x80z"));                          // lone continuation byte
  EXPECT_EQ(lj::io::dumpJson(json("a\xff")), "\"a\xEF\xBF\xBD\""); // replaced, not thrown
}

TEST(ControlPeers, OwnUidAndRootOnly) {
  EXPECT_TRUE(ControlSocket::allowedPeer(0));
  EXPECT_TRUE(ControlSocket::allowedPeer(::geteuid()));
  EXPECT_FALSE(ControlSocket::allowedPeer(::geteuid() + 1 == 0 ? 2 : ::geteuid() + 1));
}

} // namespace
