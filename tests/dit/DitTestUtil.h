// Helpers shared by the plc.dit unit tests: a small valid container and hash-correct variants.
#pragma once

#include "formats/PlcDit.h"

#include <string>

namespace lj::dittest {

/// Insert a correct `hash = ...` line after the magic line of a canonical body (docs/plc-dit.md
/// "Content hash": a body written canonically is its own canonical serialization).
inline std::string withHash(const std::string &canonicalBody) {
  size_t nl = canonicalBody.find('\n') + 1;
  return canonicalBody.substr(0, nl) + "hash = " + formats::sha256Hash(canonicalBody) + "\n" +
         canonicalBody.substr(nl);
}

/// A canonical body with two symbols, one P value and a three-line program.
inline std::string smallBody() {
  return "ladderjit-plc-dit 1\n"
         "[params]\n"
         "plc2_nvalue = 50\n"
         "period_ms = 10\n"
         "P12 = 345\n"
         "[symbols]\n"
         "START X1.0 # start key\n"
         "COUNT D5\n"
         "[program]\n"
         "LD START\n"
         "OUT Y0.0\n"
         "MOV 7 COUNT\n"
         "[end]\n";
}

/// parseDit's error for `text`, or "" when it parses.
inline std::string errorOf(const std::string &text) {
  std::string error;
  return formats::parseDit(text, "t.dit", error) ? std::string() : error;
}

} // namespace lj::dittest
