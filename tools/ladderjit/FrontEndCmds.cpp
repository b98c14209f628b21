// `check`, `emit-llvm` and `fuzz`: the commands that load a program (STL or plc.dit) without
// simulating it (or, for fuzz, generate their own).
#include "tools/ladderjit/Commands.h"
#include "tools/ladderjit/Progress.h"

#include "engines/LlvmBackend.h"
#include "ir/Diagnostics.h"
#include "pipeline/Compile.h"

#include "fuzz/EditFuzz.h"
#include "fuzz/Fuzz.h"

#include <cstdio>
#include <iostream>

namespace lj::cli {

int usageError(const std::string &msg) {
  // A value quoted from input (--set, --stimulus, --params, --watch, --modbus-map, a monitor
  // reply) may hold any byte: control bytes are written as \xNN, as in diagnostics.
  std::fprintf(stderr, "ladderjit: error: %s\n", printable(msg).c_str());
  return kUsage;
}

bool readProgram(const std::string &path, ProgramSource &src, int &exitCode,
                 std::string_view dialect) {
  if (Status st = pipeline::readProgramFile(path, src, dialect); !st.ok()) {
    exitCode = usageError(st.message());
    return false;
  }
  exitCode = kOk;
  return true;
}

std::optional<VerifiedProgram> loadProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                           int &exitCode) {
  std::string diagnostics;
  std::optional<VerifiedProgram> prog = pipeline::verifyProgram(src, plc2Nvalue, diagnostics);
  if (!diagnostics.empty()) std::fputs(diagnostics.c_str(), stderr);
  exitCode = prog ? kOk : kProgramErrors;
  return prog;
}

std::optional<VerifiedProgram> loadProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                           int &exitCode, WarningReport report,
                                           std::string_view dialect) {
  if (report == WarningReport::All) return loadProgram(src, plc2Nvalue, exitCode);
  std::string diagnostics;
  size_t warnings = 0;
  std::optional<VerifiedProgram> prog =
      pipeline::verifyProgram(src, plc2Nvalue, diagnostics, &warnings);
  exitCode = prog ? kOk : kProgramErrors;
  if (!prog) { // errors: everything, the warnings beside them may explain them
    std::fputs(diagnostics.c_str(), stderr);
    return prog;
  }
  if (report == WarningReport::Summary && warnings > 0)
    std::fputs(warningSummary(src.path, warnings, dialect).c_str(), stderr);
  return prog;
}

std::string warningSummary(const std::string &path, size_t count, std::string_view dialect) {
  if (count == 0) return {};
  std::string cmd = "ladderjit check ";
  if (!dialect.empty()) cmd += "--dialect " + std::string(dialect) + " ";
  return "ladderjit: " + printable(path) + ": " + std::to_string(count) + " verifier warning" +
         (count == 1 ? "" : "s") + "; `" + cmd + printable(path) + "` lists them\n";
}

int runCheck(const CheckArgs &a) {
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  std::optional<VerifiedProgram> prog =
      loadProgram(src, effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven), code);
  if (!prog) return code;
  if (a.print) std::cout << pipeline::printProgram(*prog) << std::flush;
  return kOk;
}

int runEmitLlvm(const EmitArgs &a) {
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  std::optional<VerifiedProgram> prog =
      loadProgram(src, effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven), code);
  if (!prog) return code;
  std::string ir, error;
  const engines::LlvmBackend *llvm = engines::llvmBackend(error);
  if (!llvm) return usageError("emit-llvm: " + error);
  if (!llvm->emitLlvm(*prog, a.optLevel, ir, error))
    return usageError("emit-llvm failed: " + error);
  std::cout << ir << std::flush;
  return kOk;
}

int runFuzz(const FuzzArgs &a) {
  // The generators write HNC-8 STL (gen/RandomProgram.cpp), FANUC PMC (gen/FanucProgram.cpp),
  // IEC IL (gen/IlGenerator.cpp) and ClassicLadder projects (gen/ClpGenerator.cpp).
  Result<const pipeline::Dialect *> dialect =
      pipeline::dialectForOption(a.dialect.empty() ? "hnc8" : a.dialect);
  if (!dialect) return usageError(dialect.status().message());
  const pipeline::Dialect *d = *dialect;
  const bool fanuc = std::string_view(d->name) == "fanuc";
  const bool iec = std::string_view(d->name) == "iec";
  const bool clp = std::string_view(d->name) == "classicladder";
  if (d != &pipeline::defaultDialect() && !fanuc && !iec && !clp)
    return usageError(
        std::string(
            "fuzz generates only hnc8, fanuc, iec and classicladder programs, not dialect '") +
        d->name + "'");
  if (clp && (a.edit || a.roundTrip || a.switches || a.trace))
    return usageError("fuzz --dialect classicladder takes no --edit, --round-trip, --switch or "
                      "--trace");
  if (a.edit) {
    if (a.roundTrip || a.switches || a.trace)
      return usageError("--edit excludes --round-trip, --switch and --trace");
    fuzz::EditFuzzOptions eo;
    eo.dialect = d->name;
    eo.seed = a.seed;
    eo.programs = a.programs;
    eo.ticks = a.ticks;
    Progress progress;
    if (progress.enabled()) {
      double lastShown = 0;
      eo.progress = [&progress, &lastShown, total = a.programs](uint64_t done, uint64_t failures,
                                                                double seconds) {
        if (seconds < 1.0 || seconds - lastShown < 0.25) return;
        lastShown = seconds;
        double rate = static_cast<double>(done) / seconds;
        char line[200];
        std::snprintf(line, sizeof line,
                      "fuzz --edit: grids %llu/%llu, %.0f/s, mismatches %llu, %.0f s left",
                      static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                      rate, static_cast<unsigned long long>(failures),
                      rate > 0 ? static_cast<double>(total - done) / rate : 0.0);
        progress.show(line);
      };
    }
    fuzz::EditFuzzStats st = fuzz::runEdit(eo, std::cout);
    progress.clear();
    std::cout << std::flush;
    return st.failures() == 0 ? kOk : kProgramErrors;
  }
  fuzz::FuzzOptions opts;
  opts.fanuc = fanuc;
  opts.iec = iec;
  opts.classicladder = clp;
  opts.seed = a.seed;
  opts.programs = a.programs;
  opts.ticks = a.ticks;
  opts.roundTrip = a.roundTrip;
  opts.switches = a.switches;
  if (a.roundTrip && a.switches) return usageError("--switch and --round-trip exclude each other");
  opts.trace = a.trace;
  if (a.trace && a.switches) return usageError("--switch and --trace exclude each other");
  if (a.trace && a.roundTrip) return usageError("--trace and --round-trip exclude each other");
  // Programs done, rate, mismatches so far and time left, once the campaign has run a second;
  // only on a terminal (CLI.md: nothing extra on a redirected stderr).
  Progress progress;
  if (progress.enabled()) {
    double lastShown = 0;
    opts.progress = [&progress, &lastShown, total = a.programs](const fuzz::FuzzStats &st,
                                                                uint64_t done) {
      if (done == 0) return progress.clear();
      if (st.seconds < 1.0 || st.seconds - lastShown < 0.25) return;
      lastShown = st.seconds;
      double rate = static_cast<double>(done) / st.seconds;
      char line[200];
      std::snprintf(line, sizeof line,
                    "fuzz: programs %llu/%llu, %.0f/s, mismatches %llu, %.0f s left",
                    static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                    rate, static_cast<unsigned long long>(st.failures()),
                    rate > 0 ? static_cast<double>(total - done) / rate : 0.0);
      progress.show(line);
    };
  }
  uint64_t mismatches = fuzz::run(opts, std::cout);
  std::cout << std::flush;
  return mismatches == 0 ? kOk : kProgramErrors;
}

} // namespace lj::cli
