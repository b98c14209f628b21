// The `ladderjit` driver: CLI11 subcommands exactly as the command-line contract (CLI.md; README
// "Commands"); the work is in the command functions (Commands.h). Usage errors exit 2, never a
// crash or an exception.
#include "tools/ladderjit/Commands.h"

#include "ir/Diagnostics.h"
#include "pipeline/Dialects.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>

namespace {

using namespace lj::cli;

// One value per occurrence, so `--set A=1 PROGRAM` never swallows PROGRAM.
template <typename T>
CLI::Option *repeatable(CLI::App *app, const char *name, T &v, const char *help) {
  return app->add_option(name, v, help)->expected(1)->allow_extra_args(false)->take_all();
}

// Non-negative integer options: plain decimal digits that fit in 64 bits. CLI11 alone would
// wrap "-5" to 2^64 - 5 for an unsigned option, turning a typo into an endless run.
const CLI::Validator kUnsigned(
    [](std::string &text) -> std::string {
      uint64_t v = 0;
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (text.empty() || ec != std::errc() || end != text.data() + text.size())
        return "expected a non-negative integer, got '" + text + "'";
      return {};
    },
    "UINT");

// --plc2-nvalue (an int32 count): digits up to 2^31 - 1, so an over-large value is named
// instead of CLI11's bare "Could not convert".
const CLI::Validator kNvalue(
    [](std::string &text) -> std::string {
      uint64_t v = 0;
      auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
      if (text.empty() || ec != std::errc() || end != text.data() + text.size() ||
          v > uint64_t{INT32_MAX})
        return "expected an integer 0..2147483647, got '" + text + "'";
      return {};
    },
    "UINT");

// A single-valued option given twice: the last one wins, as in most command-line tools.
CLI::Option *lastWins(CLI::Option *o) {
  return o->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

const char *const kProgramHelp = "program file (.stl, plc.dit, .pmc, .il, .clp) or its ladder JSON "
                                 "(.json)";

/// --dialect's help, from the dialects of this build and their extensions.
std::string dialectHelp() {
  std::string names, exts;
  for (const lj::pipeline::Dialect *d : lj::pipeline::allDialects()) {
    names += (names.empty() ? "" : " | ") + std::string(d->name);
    std::string e;
    for (const char *x : d->extensions) e += (e.empty() ? "" : "/") + std::string(x);
    exts += (exts.empty() ? "" : ", ") + e + " " + d->name;
  }
  return "dialect of PROGRAM: " + names + " (default: by extension, " + exts +
         ", .json as it names; other names " + lj::pipeline::defaultDialect().name + ")";
}

int mainImpl(int argc, char **argv) {
  CLI::App app{"ladderjit: CNC PLC programs in HNC-8 STL (.stl, plc.dit), FANUC 0i-D PMC "
               "mnemonics (.pmc), IEC 61131-3 IL of the Modicon Neza (.il) and LinuxCNC "
               "ClassicLadder projects (.clp), or their ladder network JSON, checked, drawn as "
               "ladder and run in a reference interpreter, an LLVM "
               "JIT or an AOT shared object; `serve` is the real-time runtime with a live ladder "
               "view, and the HAL component ladderjit.so runs a compiled program in LinuxCNC "
               "(docs/linuxcnc.md)",
               "ladderjit"};
  app.require_subcommand(1);
  // A value quoted in a parse error may hold any byte: control bytes as \xNN (ir/Diagnostics.h).
  app.failure_message([](const CLI::App *a, const CLI::Error &e) {
    std::string s = CLI::FailureMessage::simple(a, e);
    size_t nl = s.find('\n');
    return lj::printable(s.substr(0, nl)) + (nl == std::string::npos ? "" : s.substr(nl));
  });
  app.set_version_flag("--version", "ladderjit 0.1.0");

  CheckArgs check;
  CLI::App *cCheck = app.add_subcommand("check", "parse and verify; print diagnostics");
  lastWins(cCheck->add_option("--dialect", check.dialect, dialectHelp()));
  cCheck->add_option("PROGRAM", check.program, kProgramHelp)->required();
  cCheck->add_flag("--print", check.print, "print the verified program");
  CLI::Option *checkNvalue = lastWins(
      cCheck->add_option("--plc2-nvalue", check.plc2Nvalue, "PLC2 statements per tick (0 = all)")
          ->check(kNvalue));

  RunArgs run;
  CLI::App *cRun = app.add_subcommand("run", "simulate ticks and print the watch table");
  lastWins(cRun->add_option("--dialect", run.dialect, dialectHelp()));
  cRun->add_option("PROGRAM", run.program, kProgramHelp)->required();
  lastWins(cRun->add_option("--engine", run.engine, "interp | jit | aot:PATH.so (default jit)"));
  lastWins(cRun->add_option("--ticks", run.ticks, "number of ticks (default 1)")->check(kUnsigned));
  CLI::Option *runPeriod =
      lastWins(cRun->add_option("--period-ms", run.periodMs,
                                "PLC1 period in ms (default: the plc.dit's, else 1)")
                   ->check(kUnsigned));
  CLI::Option *runNvalue =
      lastWins(cRun->add_option("--plc2-nvalue", run.plc2Nvalue,
                                "PLC2 statements per tick (default: the plc.dit's, else 200)")
                   ->check(kNvalue));
  lastWins(cRun->add_option("--max-backward-steps", run.maxBackwardSteps,
                            "watchdog limit per tick (default 1000000)")
               ->check(kUnsigned));
  repeatable(cRun, "--set", run.sets, "ADDR=VALUE applied before init; repeatable");
  lastWins(cRun->add_option("--stimulus", run.stimulus, "file of '@TICK ADDR=VALUE ...' lines"));
  repeatable(cRun, "--watch", run.watch, "ADDR[,ADDR...] printed after every tick; repeatable");
  lastWins(cRun->add_option("--format", run.format, "csv | jsonl (default csv)"));
  lastWins(
      cRun->add_option("--dump", run.dump, "write the final state as JSON to FILE ('-' = stdout)"));
  lastWins(cRun->add_option("--params", run.params,
                            "P values, 'P12=345' per line (FANUC: COUNTER = BCD|BINARY and PMC "
                            "parameters, docs/fanuc-pmc.md)"));
  repeatable(cRun, "--trust-key", run.trustKeys,
             "public key whose aot .so files are accepted; repeatable (default: the default "
             "key pair's, docs/aot.md)");
  lastWins(cRun->add_option("--tier", run.tier,
                            "direct | interp-first | interp-fast-opt (default direct; "
                            "docs/serve.md \"Tiering\")"));
  lastWins(cRun->add_option("--tier-switch-tick", run.tierSwitchTicks,
                            "N[,M]: take the background JIT code exactly before tick N (and M)"));
  lastWins(cRun->add_option("--vcd", run.vcd,
                            "write the --watch addresses of every tick as a value change dump "
                            "(docs/trace.md)"));
  cRun->add_flag("--vcd-bits", run.vcdBits,
                 "--vcd: each byte/word as its bit wires NAME[0].. instead of one vector (for "
                 "PulseView 0.4 / libsigrok 0.5)");
  cRun->add_flag("--quiet", run.quiet, "not even the one line that counts verifier warnings");

  EmitArgs emit;
  CLI::App *cEmit = app.add_subcommand("emit-llvm", "print the LLVM IR the JIT would compile");
  lastWins(cEmit->add_option("--dialect", emit.dialect, dialectHelp()));
  cEmit->add_option("PROGRAM", emit.program, kProgramHelp)->required();
  lastWins(cEmit->add_option("-O", emit.optLevel, "optimization level 0..3 (default 2)")
               ->check(CLI::Range(0, 3)));
  CLI::Option *emitNvalue =
      lastWins(cEmit
                   ->add_option("--plc2-nvalue", emit.plc2Nvalue,
                                "PLC2 statements per tick (default: the plc.dit's, else 200)")
                   ->check(kNvalue));

  DitArgs dit;
  CLI::App *cDit = app.add_subcommand("dit", "write a plc.dit container from an STL file");
  lastWins(cDit->add_option("--dialect", dit.dialect, dialectHelp()));
  cDit->add_option("PROGRAM", dit.program, "STL file")->required();
  lastWins(cDit->add_option("--symbols", dit.symbols, "symbols file, 'NAME ADDR [comment]' lines"));
  lastWins(cDit->add_option("--params", dit.params, "P values, 'P12=345' per line"));
  lastWins(
      cDit->add_option("--plc2-nvalue", dit.plc2Nvalue, "PLC2 statements per tick (default 200)")
          ->check(kNvalue));
  lastWins(cDit->add_option("--period-ms", dit.periodMs, "PLC1 period in ms (default 1)")
               ->check(kUnsigned));
  lastWins(cDit->add_option("-o,--output", dit.output, "container to write ('-' = stdout)"))
      ->required();

  FuzzArgs fz;
  CLI::App *cFuzz = app.add_subcommand("fuzz", "differential test: interpreter against JIT");
  lastWins(cFuzz->add_option("--dialect", fz.dialect, dialectHelp()));
  lastWins(cFuzz->add_option("--seed", fz.seed, "random seed (default 1)")->check(kUnsigned));
  lastWins(cFuzz->add_option("--programs", fz.programs, "number of programs (default 1000)")
               ->check(kUnsigned));
  lastWins(
      cFuzz->add_option("--ticks", fz.ticks, "ticks per program (default 50)")->check(kUnsigned));
  cFuzz->add_flag("--trace", fz.trace,
                  "build the interpreter and the JIT traced and compare their power-flow traces "
                  "too (ir/Trace.h, the live ladder view)");
  cFuzz->add_flag("--round-trip", fz.roundTrip,
                  "each program against its ladder round trip (STL -> networks -> JSON -> STL), "
                  "on the interpreter; fanuc / iec: program -> networks -> JSON -> networks -> "
                  "program text in the dialect -> front end, whose networks must hold the same "
                  "statements (every program printed)");
  cFuzz->add_flag("--switch", fz.switches,
                  "switch engines (interp, JIT fast, JIT optimizing) at random ticks on one "
                  "state, against an unswitched interpreter run (docs/serve.md \"Tiering\")");
  cFuzz->add_flag("--edit", fz.edit,
                  "editor grids and random edits: each grid's program on the interpreter against "
                  "the grid evaluator tick for tick, and grid -> program -> networks -> grid "
                  "(docs/ladder-edit.md \"Grid and oracle\")");

  BenchArgs bn;
  CLI::App *cBench = app.add_subcommand(
      "bench", "compile phases and scan times of PROGRAM per engine and tier (docs/bench.md)");
  lastWins(cBench->add_option("--dialect", bn.dialect, dialectHelp()));
  cBench->add_option("PROGRAM", bn.program, kProgramHelp);
  cBench->add_flag("--corpus", bn.corpus,
                   "instead of PROGRAM: every shape of the benchmark shape corpus on jit-opt, aot, "
                   "gcc and clang -O1/-O2, with the ratio to the best C per shape");
  lastWins(cBench
               ->add_option("--rounds", bn.rounds,
                            "--corpus: rounds of --scans scans per shape (default 9)")
               ->check(kUnsigned));
  lastWins(cBench->add_option("--shapes", bn.shapes,
                              "--corpus: comma-separated shape names (default: all)"));
  lastWins(cBench
               ->add_option("--statements", bn.statements,
                            "--corpus: statements per shape (default 10000)")
               ->check(kUnsigned));
  lastWins(cBench->add_option("--keep-programs", bn.keepPrograms,
                              "--corpus: also write the generated programs into this directory"));
  lastWins(cBench->add_option("--engine", bn.engine, "interp | jit | aot | all (default all)"));
  lastWins(cBench->add_option("--tier", bn.tier, "fast | opt | both (default both)"));
  lastWins(cBench->add_option("--scans", bn.scans, "timed full scans per engine (default 2000)")
               ->check(kUnsigned));
  lastWins(cBench->add_option("--stimulus", bn.stimulus,
                              "inputs from a file of '@TICK ADDR=VALUE ...' lines (default: "
                              "pseudo-random X bits and F words)"));
  lastWins(cBench->add_option("--format", bn.format, "text | json (default text)"));
  lastWins(cBench->add_option("--seed", bn.seed, "seed of the pseudo-random inputs (default 1)")
               ->check(kUnsigned));
  cBench->add_flag("--cache", bn.cache, "compile through the object cache (default: off)");
  cBench->add_flag("--quiet", bn.quiet, "not even the one line that counts verifier warnings");
  cBench->add_flag("--trace", bn.trace,
                   "also time the traced builds of the live view (interp-traced, jit-*-traced)");
  cBench->add_flag("--c-baseline", bn.cBaseline,
                   "also translate PROGRAM to C and build it with gcc and clang at -O1/-O2");
  lastWins(
      cBench
          ->add_option("--c-timeout", bn.cTimeoutS, "seconds one C compile may take (default 300)")
          ->check(kUnsigned));
  CLI::Option *benchNvalue =
      lastWins(cBench
                   ->add_option("--plc2-nvalue", bn.plc2Nvalue,
                                "PLC2 statements per tick (default: the plc.dit's, else 200)")
                   ->check(kNvalue));

  LadderArgs lad;
  CLI::App *cLadder = app.add_subcommand(
      "ladder", "the program as ladder networks (text, json) or drawn (svg, html, layout json)");
  lastWins(cLadder->add_option("--dialect", lad.dialect, dialectHelp()));
  cLadder->add_option("PROGRAM", lad.program, kProgramHelp)->required();
  lastWins(cLadder->add_option("--format", lad.format,
                               "text | json | svg | html | layout (default text)"));
  lastWins(cLadder->add_option("-o,--output", lad.output, "file to write (default stdout)"));
  cLadder->add_flag("--quiet", lad.quiet, "not even the one line that counts verifier warnings");
  CLI::Option *ladNvalue = lastWins(
      cLadder->add_option("--plc2-nvalue", lad.plc2Nvalue, "PLC2 statements per tick (0 = all)")
          ->check(kNvalue));

  CompileArgs comp;
  CLI::App *cCompile =
      app.add_subcommand("compile", "ahead-of-time build to a shared object with the C ABI");
  cCompile->add_option("PROGRAM", comp.program, kProgramHelp)->required();
  lastWins(cCompile->add_option("--dialect", comp.dialect, dialectHelp()));
  lastWins(cCompile->add_option("-o,--output", comp.output, "shared object to write"))->required();
  lastWins(cCompile->add_option("--cpu", comp.cpu, "host | generic (default host)"));
  CLI::Option *compNvalue =
      lastWins(cCompile
                   ->add_option("--plc2-nvalue", comp.plc2Nvalue,
                                "PLC2 statements per tick (default: the plc.dit's, else 200)")
                   ->check(kNvalue));
  lastWins(cCompile->add_option("--sign-key", comp.signKey,
                                "private key to sign with (default: the default key pair, created "
                                "on first use; docs/aot.md)"));
  lastWins(cCompile->add_option("--cc-timeout", comp.ccTimeout,
                                "seconds the C compiler may take before it is killed (default "
                                "120, or $LADDERJIT_CC_TIMEOUT; docs/aot.md)"));

  KeygenArgs keygen;
  CLI::App *cKeygen = app.add_subcommand("keygen", "new key pair to sign AOT shared objects");
  lastWins(cKeygen->add_option("-o,--output", keygen.output,
                               "DIR/NAME: writes NAME.key (private) and NAME.pub"))
      ->required();

  ServeArgs serve;
  CLI::App *cServe = app.add_subcommand("serve", "real-time runtime (docs/serve.md)");
  lastWins(cServe->add_option("--dialect", serve.dialect, dialectHelp()));
  cServe->add_option("PROGRAM", serve.program, kProgramHelp)->required();
  lastWins(
      cServe->add_option("--engine", serve.engine, "jit | interp | aot:PATH.so (default jit)"));
  lastWins(cServe->add_option("--tier", serve.tier,
                              "direct | interp-first | interp-fast-opt (default interp-fast-opt "
                              "with --engine jit; docs/serve.md \"Tiering\")"));
  CLI::Option *servePeriod =
      lastWins(cServe->add_option("--period-ms", serve.periodMs, "PLC1 period in ms (default 1)")
                   ->check(kUnsigned));
  CLI::Option *serveNvalue =
      lastWins(cServe
                   ->add_option("--plc2-nvalue", serve.plc2Nvalue,
                                "PLC2 statements per tick (default: the plc.dit's, else 200)")
                   ->check(kNvalue));
  lastWins(cServe
               ->add_option("--max-backward-steps", serve.maxBackwardSteps,
                            "watchdog limit per tick (default 1000000)")
               ->check(kUnsigned));
  lastWins(cServe->add_option("--modbus", serve.modbus, "Modbus TCP server on [HOST:]PORT"));
  lastWins(cServe->add_option("--modbus-map", serve.modbusMap,
                              "Modbus map file of the program's addresses (docs/modbus-map.md; "
                              "needed for FANUC and IEC programs)"));
  lastWins(cServe->add_option("--http", serve.http,
                              "the live ladder view on [HOST:]PORT (HOST defaults to 127.0.0.1)"));
  lastWins(cServe->add_option("--http-token-file", serve.httpTokenFile,
                              "the file of the token every live view request needs, 0600 (a "
                              "fresh token is written there when it does not exist; default: "
                              "next to the control socket)"));
  cServe->add_option("--http-host", serve.httpHosts,
                     "a Host name (NAME or NAME:PORT) the live view answers besides its "
                     "address and localhost (repeatable)");
  cServe->add_flag("--http-read-only", serve.httpReadOnly,
                   "the live view only shows: force, lock and unlock are refused (403)");
  lastWins(cServe->add_option("--retain", serve.retain, "retentive store file"));
  cServe->add_flag("--retain-force", serve.retainForce,
                   "load nothing from a retain file of another layout; start with zeros, keep "
                   "the old files as FILE.rejected (docs/retain.md)");
  lastWins(cServe
               ->add_option("--retain-period-ms", serve.retainPeriodMs,
                            "minimum gap between periodic retain saves (default 100)")
               ->check(CLI::Range(1, 60000)));
  cServe->add_flag("--modbus-write-inputs", serve.modbusWriteInputs,
                   "allow Modbus writes to X and F (simulation only)");
  lastWins(cServe->add_option("--params", serve.params,
                              "P values, 'P12=345' per line (FANUC: COUNTER = BCD|BINARY and PMC "
                              "parameters, docs/fanuc-pmc.md)"));
  repeatable(cServe, "--set", serve.sets, "ADDR=VALUE at power-up; repeatable");
  cServe->add_flag("--quiet", serve.quiet, "not even the one line that counts verifier warnings");
  lastWins(cServe->add_option("--trace", serve.trace,
                              "signal trace definition file, armed at start (docs/trace.md)"));
  lastWins(cServe
               ->add_option("--duration", serve.duration,
                            "seconds to run (default: until "
                            "SIGINT/SIGTERM)")
               ->check(kUnsigned));
  lastWins(cServe->add_option("--stats", serve.stats, "write timing statistics as JSON at exit"));
  lastWins(cServe->add_option("--control", serve.control,
                              "control socket (default <runtime dir>/serve-<pid>.sock)"));
  lastWins(cServe
               ->add_option("--client-idle-s", serve.clientIdleS,
                            "close control / Modbus connections idle this long (default 30)")
               ->check(CLI::Range(1, 86400)));
  lastWins(cServe
               ->add_option("--request-timeout-ms", serve.requestTimeoutMs,
                            "a control / Modbus request must arrive whole within this (default "
                            "2000)")
               ->check(CLI::Range(100, 600000)));
  lastWins(cServe->add_option("--shm", serve.shm, "shared-memory process image NAME"));
  lastWins(cServe->add_option("--io", serve.io, "simnc | shm: who writes F (default simnc)"));
  lastWins(cServe->add_option("--rt-priority", serve.rtPriority, "SCHED_FIFO priority 1..99")
               ->check(CLI::Range(1, 99)));
  lastWins(cServe->add_option("--cpu", serve.cpu, "pin the scan thread to this CPU")
               ->check(CLI::Range(0, 1023)));
  repeatable(cServe, "--trust-key", serve.trustKeys,
             "public key whose aot .so files are accepted; repeatable (default: the default "
             "key pair's, docs/aot.md)");
  repeatable(cServe, "--load-dir", serve.loadDirs,
             "directory `monitor load` may read from; repeatable (default: PROGRAM's)");
  cServe->add_flag("--watch-file", serve.watchFile,
                   "online change when PROGRAM (or the .so) changes on disk");

  MonitorArgs mon;
  CLI::App *cMonitor = app.add_subcommand("monitor", "talk to a running serve: read, write, "
                                                     "force, lock, unlock, locks, load, stats, "
                                                     "trace, stop");
  lastWins(cMonitor->add_option("--control", mon.control,
                                "control socket (default: the only server in the runtime dir)"));
  cMonitor->add_flag("--allow-shrink", mon.allowShrink,
                     "load: accept an empty program or one without a part the running one has");
  cMonitor->add_option("COMMAND", mon.args, "command and its arguments")->required();
  bool traceVcd = false, traceCsv = false, traceBits = false;
  cMonitor->add_flag("--vcd", traceVcd, "trace save: as a value change dump (the default)");
  cMonitor->add_flag("--csv", traceCsv, "trace save: as CSV");
  cMonitor->add_flag("--bits", traceBits, "trace save --vcd: each byte/word as its bit wires");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion &e) {
    return app.exit(e);
  } catch (const CLI::ParseError &e) {
    app.exit(e); // prints the message and a hint
    return kUsage;
  }

  check.plc2NvalueGiven = checkNvalue->count() > 0;
  run.periodMsGiven = runPeriod->count() > 0;
  run.plc2NvalueGiven = runNvalue->count() > 0;
  emit.plc2NvalueGiven = emitNvalue->count() > 0;
  comp.plc2NvalueGiven = compNvalue->count() > 0;
  lad.plc2NvalueGiven = ladNvalue->count() > 0;
  bn.plc2NvalueGiven = benchNvalue->count() > 0;

  if (cCheck->parsed()) return runCheck(check);
  if (cDit->parsed()) return runDit(dit);
  if (cRun->parsed()) return runRun(run);
  if (cEmit->parsed()) return runEmitLlvm(emit);
  if (cFuzz->parsed()) return runFuzz(fz);
  if (cCompile->parsed()) return runCompile(comp);
  if (cKeygen->parsed()) return runKeygen(keygen);
  if (cLadder->parsed()) return runLadder(lad);
  if (cBench->parsed()) return runBench(bn);
  if (cServe->parsed()) {
    serve.periodMsGiven = servePeriod->count() > 0;
    serve.plc2NvalueGiven = serveNvalue->count() > 0;
    return runServe(serve);
  }
  if (cMonitor->parsed()) {
    // `trace save FILE --csv`: the flags go back behind the command (MonitorCmd.cpp reads them).
    if (traceVcd) mon.args.push_back("--vcd");
    if (traceCsv) mon.args.push_back("--csv");
    if (traceBits) mon.args.push_back("--bits");
    return runMonitor(mon);
  }
  return usageError("no subcommand");
}

} // namespace

// Output that did not reach stdout (a full disk, /dev/full, a closed pipe) is a failure, not
// exit 0: flush it and look at the stream's error flag (cout shares stdout's buffer).
int lj::cli::checkStdout(int code) {
  std::cout.flush();
  errno = 0;
  bool failed = std::fflush(stdout) != 0 || std::ferror(stdout) || !std::cout.good();
  if (!failed) return code;
  std::fprintf(stderr, "ladderjit: error: cannot write to standard output%s%s\n", errno ? ": " : "",
               errno ? std::strerror(errno) : "");
  return code == kOk ? kUsage : code;
}

namespace {
int64_t gMainStartNs = 0;
} // namespace

int64_t lj::cli::mainStartNs() { return gMainStartNs; }

int main(int argc, char **argv) {
  gMainStartNs = std::chrono::duration_cast<std::chrono::nanoseconds>(
                     std::chrono::steady_clock::now().time_since_epoch())
                     .count();
  // Last line of defence: an exception (bad_alloc, a JSON error) must not end in a core dump.
  try {
    return lj::cli::checkStdout(mainImpl(argc, argv));
  } catch (const std::exception &e) {
    std::fprintf(stderr, "ladderjit: error: %s\n", e.what());
  } catch (...) {
    std::fprintf(stderr, "ladderjit: error: unexpected exception\n");
  }
  return kUsage;
}
