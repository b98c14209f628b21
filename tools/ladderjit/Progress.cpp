#include "tools/ladderjit/Progress.h"

#include <unistd.h>

#include <cstdio>

namespace lj::cli {

Progress::Progress()
    : tty_(::isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()) {}

void Progress::show(const std::string &line) {
  if (!tty_ || std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  std::string out = "\r" + line;
  if (line.size() < lastLen_) out += std::string(lastLen_ - line.size(), ' ');
  lastLen_ = line.size();
  std::fputs(out.c_str(), stderr);
  std::fflush(stderr);
}

void Progress::clear() {
  if (!tty_ || lastLen_ == 0) return;
  std::fprintf(stderr, "\r%s\r", std::string(lastLen_, ' ').c_str());
  std::fflush(stderr);
  lastLen_ = 0;
}

} // namespace lj::cli
