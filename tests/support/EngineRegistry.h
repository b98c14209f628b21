// The registry of engines every execution test runs on (interpreter, JIT, ...).
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"

#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace lj::signing {
class SigningKey;
class TrustedKeys;
} // namespace lj::signing

namespace lj::test {

/// Builds one engine for a verified program (which outlives the engine). Returns null and sets
/// `error` when the engine cannot be built.
using MakeEngineFn =
    std::function<std::unique_ptr<Engine>(const VerifiedProgram &prog, std::string &error)>;

/// One registered engine: a short name (used in test names, so [A-Za-z0-9_]) and its factory.
struct EngineFactory {
  std::string name;
  MakeEngineFn make;
};

/// Every registered engine, the reference interpreter first. To add an engine, give it an
/// EngineKind in engines/EngineSpec.h and add ONE line to the list in EngineRegistry.cpp.
const std::vector<EngineFactory> &registeredEngines();

/// The key pair of the "aot" engine: an in-memory Ed25519 key made once per test process, and
/// the trust set holding only its public key (docs/aot.md "Trust").
const signing::SigningKey &testSigningKey();
const signing::TrustedKeys &testTrust();

/// GoogleTest prints parameters with this.
inline std::ostream &operator<<(std::ostream &os, const EngineFactory &f) { return os << f.name; }

} // namespace lj::test
