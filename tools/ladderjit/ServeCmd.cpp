// `ladderjit serve`: the real-time runtime (docs/serve.md) as runtime/Server.h runs it. The
// driver only parses the options (Main.cpp) and handles the signals: SIGINT / SIGTERM stop the
// server, as do `monitor stop`, --duration and the scan thread ending.
#include "tools/ladderjit/Commands.h"

#include "runtime/Server.h"

#include <signal.h>
#include <time.h>

#include <cstdio>
#include <cstdlib>

namespace lj::cli {

int runServe(const ServeArgs &args) {
  rt::ServerOptions opts = args;
  opts.startNs = mainStartNs();
  rt::Server server(std::move(opts));
  if (Status s = server.load(); !s.ok()) {
    // Diagnostics of PROGRAM exit 1; an unreadable file or a .so that does not fit exits 2.
    if (s.code() != ErrorCode::Rejected) return usageError(s.message());
    std::fprintf(stderr, "%s\n", s.message().c_str());
    return kProgramErrors;
  }
  if (!args.quiet)
    std::fputs(warningSummary(args.program, server.warnings(), args.dialect).c_str(), stderr);
  // Signals are taken synchronously by this thread (sigtimedwait): block them before any
  // thread starts so every thread inherits the mask.
  sigset_t sigs;
  sigemptyset(&sigs);
  sigaddset(&sigs, SIGINT);
  sigaddset(&sigs, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &sigs, nullptr);
  if (Status s = server.start(); !s.ok()) return usageError(s.message());

  const std::string why = server.waitForStop([&sigs](double wait) -> const char * {
    timespec timeout{
        static_cast<time_t>(wait),
        static_cast<long>((wait - static_cast<double>(static_cast<time_t>(wait))) * 1e9)};
    int sig = sigtimedwait(&sigs, nullptr, &timeout);
    if (sig == SIGINT) return "SIGINT";
    if (sig == SIGTERM) return "SIGTERM";
    return nullptr;
  });
  int code = kOk;
  if (Status s = server.shutdown(why); !s.ok()) code = usageError(s.message());
  if (server.mustExitFast()) { // threads still compile: end them with the process, no destructors
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(code);
  }
  return code;
}

} // namespace lj::cli
