// The progress line of the long commands (`bench`, `fuzz`): one `\r`-rewritten line on stderr,
// only when stderr is a terminal and only once the command has run a second; silent otherwise.
#pragma once

#include <chrono>
#include <string>

namespace lj::cli {

class Progress {
public:
  Progress();
  bool enabled() const { return tty_; }
  /// Replace the line with `line` (nothing in the first second, nothing without a terminal).
  void show(const std::string &line);
  /// Erase the line (before the command's own output).
  void clear();

private:
  bool tty_ = false;
  size_t lastLen_ = 0;
  std::chrono::steady_clock::time_point start_;
};

} // namespace lj::cli
