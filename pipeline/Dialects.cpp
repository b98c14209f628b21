// The dialects of this build (pipeline/Dialects.h). A new dialect adds its entry to kDialects
// and moves its name from kPlanned.
#include "pipeline/Dialects.h"

#include "frontends/classicladder/FrontEnd.h"
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/iec/FrontEnd.h"
#include "frontends/iec/Objects.h"
#include "pipeline/Compile.h"
#include "profiles/Profiles.h"
#include "profiles/classicladder/ClassicLadderProfile.h"
#include "profiles/iec/IecProfile.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cctype>

namespace lj::pipeline {

// The command line's address syntax of each dialect is formats/Address.h's.
using formats::Assignment;
using formats::CliAddress;
using formats::formatAddress;
using formats::formatProfileAddress;
using formats::parseAddress;
using formats::parseAssignment;
using formats::parseAssignmentWith;
using formats::parseProfileAddress;
using formats::parseProfileAssignment;

namespace {

ParsedProgram parseHnc8(std::string_view text, std::string file, Diagnostics &diags,
                        const SymbolTable *symbols) {
  return parseStl(text, std::move(file), diags, symbols);
}

std::optional<VerifiedProgram> compileHnc8(std::string_view text, std::string file,
                                           const VerifyOptions &opts, Diagnostics &diags,
                                           const SymbolTable *symbols) {
  return pipeline::compileStl(text, std::move(file), opts, diags, symbols);
}

constexpr const char *kHnc8Extensions[] = {".stl", ".dit"};

const Dialect kHnc8{"hnc8",          kHnc8Extensions, profileNamed("hnc8"),
                    parseHnc8,       compileHnc8,     parseAddress,
                    parseAssignment, formatAddress,   hnc8::dialectText};

// FANUC 0i-D PMC (docs/fanuc-pmc.md): byte-addressed areas, `R100`, `R100.3`, `D100:4`.
std::optional<CliAddress> fanucAddress(std::string_view text, std::string &error) {
  return parseProfileAddress(*profileNamed("fanuc"), text, error);
}
std::optional<Assignment> fanucAssignment(std::string_view item, std::string &error) {
  return parseProfileAssignment(*profileNamed("fanuc"), item, error);
}
ParsedProgram parseFanuc(std::string_view text, std::string file, Diagnostics &diags,
                         const SymbolTable *symbols) {
  return fanuc::parsePmc(text, std::move(file), diags, symbols);
}
std::optional<VerifiedProgram> compileFanuc(std::string_view text, std::string file,
                                            const VerifyOptions &opts, Diagnostics &diags,
                                            const SymbolTable *symbols) {
  return pipeline::compilePmc(text, std::move(file), opts, diags, symbols);
}
constexpr const char *kFanucExtensions[] = {".pmc"};
const Dialect kFanuc{"fanuc",         kFanucExtensions,     profileNamed("fanuc"),
                     parseFanuc,      compileFanuc,         fanucAddress,
                     fanucAssignment, formatProfileAddress, fanuc::dialectText};

// IEC IL (Neza): `%I0.1`-style objects (frontends/iec/Objects.h) on the command line, in
// stimulus files, --watch and --dump (docs/iec-il.md "Command line").
ParsedProgram parseIec(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *) { // compileIl refuses a symbol table
  return iec::parseIl(text, std::move(file), diags);
}
std::optional<VerifiedProgram> compileIec(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols) {
  return pipeline::compileIl(text, std::move(file), opts, diags, symbols);
}

std::optional<CliAddress> parseIecAddress(std::string_view text, std::string &error) {
  std::string why;
  std::optional<iec::Object> obj = iec::parseObject(text, why);
  if (!obj) {
    error = "bad address " + why;
    return std::nullopt;
  }
  if (obj->op.kind != Operand::Kind::Bit && obj->op.kind != Operand::Kind::Reg) {
    error = "bad address '" + std::string(text.substr(0, 40)) + "': not an object";
    return std::nullopt;
  }
  if (obj->op.area == Area::Label || obj->op.area == Area::Subroutine) {
    error = "bad address '" + std::string(text.substr(0, 40)) +
            "': labels and subroutines hold no value";
    return std::nullopt;
  }
  CliAddress a;
  a.area = obj->op.area;
  a.index = obj->op.index;
  a.bit = obj->op.kind == Operand::Kind::Bit ? obj->op.bit : int8_t{-1};
  a.text = std::string(text);
  a.profile = &iec::profile(); // the objects live in lj_state.mem (profiles/iec)
  return a;
}

std::optional<Assignment> parseIecAssignment(std::string_view item, std::string &error) {
  return parseAssignmentWith(parseIecAddress, item, error, 40);
}

std::string formatIecAddress(const CliAddress &addr) {
  Operand o;
  o.kind = addr.isBit() ? Operand::Kind::Bit : Operand::Kind::Reg;
  o.area = addr.area;
  o.index = addr.index;
  o.bit = addr.bit;
  return iec::formatOperand(o);
}

constexpr const char *kIecExtensions[] = {".il"};

const Dialect kIec{"iec",           kIecExtensions,  profileNamed("iec"), parseIec,
                   compileIec,      parseIecAddress, parseIecAssignment,  formatIecAddress,
                   iec::dialectText};

std::string quoted(std::string_view s);

// ClassicLadder (docs/classicladder.md): `.clp` projects; addresses are ClassicLadder's
// variable names (`%I3`, `%Q0`, `%B7`, `%W2`) on the classicladder profile.
ParsedProgram parseClassicLadder(std::string_view text, std::string file, Diagnostics &diags,
                                 const SymbolTable *) { // compileClp refuses a symbol table
  return classicladder::parseClp(text, std::move(file), diags);
}
std::optional<VerifiedProgram> compileClassicLadder(std::string_view text, std::string file,
                                                    const VerifyOptions &opts, Diagnostics &diags,
                                                    const SymbolTable *symbols) {
  return pipeline::compileClp(text, std::move(file), opts, diags, symbols);
}

std::optional<CliAddress> parseClAddress(std::string_view text, std::string &error) {
  std::optional<classicladder::VarRef> v =
      classicladder::parseVarName(std::string(text.substr(0, 40)));
  if (!v || text.size() > 40) {
    error =
        "bad address " + quoted(text) + ": expected a ClassicLadder variable (%I3, %Q0, %B7, %W2)";
    return std::nullopt;
  }
  std::string why;
  std::optional<Operand> o = classicladder::varOperand(v->type, v->num, why);
  if (!o) {
    error = "bad address " + quoted(text) + ": " + why;
    return std::nullopt;
  }
  CliAddress a;
  a.area = o->area;
  a.index = o->index;
  a.bit = o->kind == Operand::Kind::Bit ? o->bit : int8_t{-1};
  a.text = std::string(text);
  a.profile = &classicladder::profile();
  return a;
}

std::optional<Assignment> parseClAssignment(std::string_view item, std::string &error) {
  return parseAssignmentWith(parseClAddress, item, error, 40);
}

std::string formatClAddress(const CliAddress &addr) {
  Operand o;
  o.kind = addr.isBit() ? Operand::Kind::Bit : Operand::Kind::Reg;
  o.area = addr.area;
  o.index = addr.index;
  o.bit = addr.bit;
  return classicladder::dialectText().formatOperand(o);
}

constexpr const char *kClassicLadderExtensions[] = {".clp"};

const Dialect kClassicLadder{
    "classicladder",    kClassicLadderExtensions, profileNamed("classicladder"),
    parseClassicLadder, compileClassicLadder,     parseClAddress,
    parseClAssignment,  formatClAddress,          classicladder::dialectText};

const Dialect *const kDialects[] = {&kHnc8, &kFanuc, &kIec, &kClassicLadder};

/// Dialects ladderjit plans (docs/architecture.md "Adding a dialect") and the extensions that
/// name them; a build without one says so instead of reading the file as HNC-8.
struct Planned {
  const char *name;
  const char *extension;
};
// None at present: hnc8, fanuc, iec and classicladder are all built.
constexpr std::array<Planned, 0> kPlanned{};

std::string quoted(std::string_view s) {
  std::string out = "'";
  for (char c : s.substr(0, 40)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return out + (s.size() > 40 ? "...'" : "'");
}

bool endsWith(std::string_view s, std::string_view tail) {
  if (s.size() < tail.size()) return false;
  for (size_t i = 0; i < tail.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - tail.size() + i])) != tail[i])
      return false;
  return true;
}

} // namespace

std::span<const Dialect *const> allDialects() { return kDialects; }

const Dialect *dialectNamed(std::string_view name) {
  for (const Dialect *d : kDialects)
    if (name == d->name) return d;
  return nullptr;
}

const Dialect &defaultDialect() { return kHnc8; }

std::string knownDialects() {
  std::string out;
  for (const Dialect *d : kDialects) out += (out.empty() ? "" : ", ") + std::string(d->name);
  return out;
}

Result<const Dialect *> dialectForOption(std::string_view name) {
  if (const Dialect *d = dialectNamed(name)) return d;
  const bool planned = std::any_of(std::begin(kPlanned), std::end(kPlanned),
                                   [&](const Planned &p) { return name == p.name; });
  return Status::error(
      ErrorCode::InvalidArgument,
      planned ? "dialect " + quoted(name) +
                    " is not available in this build (known: " + knownDialects() + ")"
              : "unknown dialect " + quoted(name) + " (known: " + knownDialects() + ")");
}

Result<const Dialect *> dialectForPath(std::string_view path) {
  for (const Dialect *d : kDialects)
    for (const char *ext : d->extensions)
      if (endsWith(path, ext)) return d;
  for (const Planned &p : kPlanned)
    if (endsWith(path, p.extension)) {
      return Status::error(ErrorCode::InvalidArgument,
                           std::string(path) + ": a " + p.extension + " file is dialect " +
                               quoted(p.name) + ", which is not available in this build (known: " +
                               knownDialects() + "; --dialect NAME reads it as another dialect)",
                           {std::string(path)});
    }
  return &kHnc8;
}

Result<const Dialect *> dialectOfJson(std::string_view text) {
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("dialect") || !j["dialect"].is_string())
    return &kHnc8; // the ladder JSON reader names what is wrong with the document
  const std::string name = j["dialect"].get<std::string>();
  Result<const Dialect *> d = dialectForOption(name);
  if (!d) return d.status().withContext("ladder JSON");
  return d;
}

} // namespace lj::pipeline
