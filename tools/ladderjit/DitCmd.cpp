// `ladderjit dit`: build a plc.dit container from an STL file, a symbols file and parameters.
// The program is verified (with its symbols) first, so a container never holds a broken one.
#include "tools/ladderjit/Commands.h"

#include "formats/InputFiles.h"
#include "formats/OutputFile.h"
#include "pipeline/Compile.h"

#include <cstdio>
#include <fstream>

namespace lj::cli {

namespace {

// P values from a params file: one entry per element, first position, last value (a params
// file lets later lines win, a container lists each P once).
std::vector<formats::Assignment> collapseParams(const std::vector<formats::Assignment> &in) {
  std::vector<formats::Assignment> out;
  for (const formats::Assignment &a : in) {
    bool merged = false;
    for (formats::Assignment &o : out)
      if (o.addr.index == a.addr.index) {
        o.value = a.value;
        merged = true;
      }
    if (!merged) out.push_back(a);
  }
  return out;
}

bool writeOutput(const std::string &path, const std::string &text, std::string &error) {
  return formats::writeOutputFile(path, text, error); // formats/OutputFile.h
}

} // namespace

int runDit(const DitArgs &a) {
  if (a.periodMs < 1 || a.periodMs > (uint64_t{1} << 40))
    return usageError("--period-ms: expected 1..2^40 for a plc.dit, got " +
                      std::to_string(a.periodMs));
  std::string stl, error;
  // A plc.dit holds an HNC-8 program (docs/plc-dit.md): --dialect and the name must say hnc8.
  Result<const pipeline::Dialect *> dialect = a.dialect.empty()
                                                  ? pipeline::dialectForPath(a.program)
                                                  : pipeline::dialectForOption(a.dialect);
  if (!dialect) return usageError(dialect.status().message());
  const pipeline::Dialect *d = *dialect;
  if (d != &pipeline::defaultDialect())
    return usageError(std::string("a plc.dit holds an hnc8 program, not dialect '") + d->name +
                      "'");
  if (!formats::readFile(a.program, stl, error)) return usageError(error);
  if (formats::looksLikeDit(stl))
    return usageError("'" + a.program + "' is already a plc.dit container; give the STL file");

  formats::DitFile dit;
  dit.plc2Nvalue = a.plc2Nvalue;
  dit.periodMs = a.periodMs;
  if (!formats::normalizeProgram(stl, a.program, dit.program, error)) return usageError(error);
  std::string text;
  if (!a.symbols.empty()) {
    if (!formats::readFile(a.symbols, text, error)) return usageError(error);
    if (!formats::parseSymbols(text, a.symbols, dit.symbols, error)) return usageError(error);
  }
  if (!a.params.empty()) {
    if (!formats::readFile(a.params, text, error)) return usageError(error);
    std::optional<std::vector<formats::Assignment>> ps =
        formats::parseParams(text, a.params, error);
    if (!ps) return usageError(error);
    dit.params = collapseParams(*ps);
  }

  // The STL file's own line numbers: the user fixes the STL, not the container.
  Diagnostics diags(a.program);
  VerifyOptions opts;
  opts.plc2Nvalue = a.plc2Nvalue;
  std::optional<VerifiedProgram> prog =
      pipeline::compileStl(dit.program, a.program, opts, diags, &dit.symbols);
  std::string rendered = diags.render();
  if (!rendered.empty()) std::fputs(rendered.c_str(), stderr);
  if (!prog || diags.hasErrors()) {
    std::fprintf(stderr, "ladderjit: error: no plc.dit written: '%s' has errors\n",
                 a.program.c_str());
    return kProgramErrors;
  }
  if (!writeOutput(a.output, formats::writeDit(dit), error)) return usageError(error);
  return kOk;
}

} // namespace lj::cli
