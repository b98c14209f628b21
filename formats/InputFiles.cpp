// Stimulus and parameter file parsers: line-oriented, located errors, no exceptions.
#include "formats/InputFiles.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace lj::io {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Split text into lines, dropping `#` comments; calls fn(lineNumber, content).
template <typename Fn> bool forEachLine(std::string_view text, Fn fn) {
  int32_t lineNo = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    ++lineNo;
    if (size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    if (!fn(lineNo, line)) return false;
    if (end == text.size()) break;
    pos = end + 1;
  }
  return true;
}

std::vector<std::string_view> splitBlanks(std::string_view line) {
  std::vector<std::string_view> items;
  size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && isBlank(line[i])) ++i;
    size_t start = i;
    while (i < line.size() && !isBlank(line[i])) ++i;
    if (i > start) items.push_back(line.substr(start, i - start));
  }
  return items;
}

std::string where(const std::string &file, int32_t line) {
  return file + ":" + std::to_string(line) + ": ";
}

} // namespace

std::optional<Stimulus> parseStimulus(std::string_view text, const std::string &file,
                                      std::string &error, AssignmentParser assign) {
  if (!assign) assign = parseAssignment;
  Stimulus stim;
  bool ok = forEachLine(text, [&](int32_t lineNo, std::string_view line) {
    std::vector<std::string_view> items = splitBlanks(line);
    if (items.empty()) return true;
    std::string_view head = items[0];
    if (head[0] != '@') {
      error = where(file, lineNo) + "expected '@TICK' at the start of the line, found '" +
              std::string(head) + "'";
      return false;
    }
    std::string_view digits = head.substr(1);
    bool allDigits = !digits.empty() && digits.size() <= 18;
    for (char c : digits) allDigits = allDigits && c >= '0' && c <= '9';
    if (!allDigits) {
      error = where(file, lineNo) + "bad tick '" + std::string(head) +
              "': expected '@' and a decimal tick number";
      return false;
    }
    StimulusEvent ev;
    ev.tick = std::stoull(std::string(digits));
    ev.line = lineNo;
    if (!stim.events.empty() && ev.tick < stim.events.back().tick) {
      error = where(file, lineNo) + "tick " + std::to_string(ev.tick) + " comes after tick " +
              std::to_string(stim.events.back().tick) + " (line " +
              std::to_string(stim.events.back().line) + "); ticks must not decrease";
      return false;
    }
    if (items.size() == 1) {
      error = where(file, lineNo) + "no assignment after '" + std::string(head) +
              "' (expected ADDR=VALUE)";
      return false;
    }
    if (items[1].substr(0, 3) == "nc.") { // a command of the simulated NC (SimNcParse.cpp)
      std::string why;
      std::vector<std::string_view> rest(items.begin() + 1, items.end());
      std::optional<NcCommand> c = parseNcCommand(rest, why);
      if (!c) {
        error = where(file, lineNo) + why;
        return false;
      }
      c->line = lineNo;
      ev.nc.push_back(*c);
      stim.events.push_back(std::move(ev));
      return true;
    }
    for (size_t i = 1; i < items.size(); ++i) {
      if (items[i].substr(0, 3) == "nc.") {
        error = where(file, lineNo) + "'" + std::string(items[i]) +
                "': an NC command needs a line of its own (@TICK nc.COMMAND key=value ...)";
        return false;
      }
      std::string why;
      std::optional<Assignment> a = assign(items[i], why);
      if (!a) {
        error = where(file, lineNo) + why;
        return false;
      }
      ev.sets.push_back(std::move(*a));
    }
    stim.events.push_back(std::move(ev));
    return true;
  });
  if (!ok) return std::nullopt;
  return stim;
}

std::optional<std::vector<Assignment>> parseParams(std::string_view text, const std::string &file,
                                                   std::string &error) {
  std::vector<Assignment> params;
  bool ok = forEachLine(text, [&](int32_t lineNo, std::string_view line) {
    // Spaces around '=' are allowed (a configuration file, not a command line): drop them all.
    std::string compact;
    for (char c : line)
      if (!isBlank(c)) compact.push_back(c);
    if (compact.empty()) return true;
    std::string why;
    std::optional<Assignment> a = parseAssignment(compact, why);
    if (!a) {
      error = where(file, lineNo) + why;
      return false;
    }
    if (a->addr.area != Area::Param || a->addr.isBit()) {
      error = where(file, lineNo) + "'" + a->addr.text +
              "' is not a parameter; expected Pn=VALUE (P0..P199)";
      return false;
    }
    params.push_back(std::move(*a));
    return true;
  });
  if (!ok) return std::nullopt;
  return params;
}

bool readFile(const std::string &path, std::string &out, std::string &error, size_t maxBytes) {
  // O_NONBLOCK: opening a FIFO never waits for a writer (it is refused right below).
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    error = "cannot read '" + path + "': " + std::strerror(errno);
    return false;
  }
  struct stat st;
  if (::fstat(fd, &st) != 0) {
    error = "cannot read '" + path + "': " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  if (!S_ISREG(st.st_mode)) {
    error = "cannot read '" + path +
            "': " + (S_ISDIR(st.st_mode) ? std::string("is a directory") : "not a regular file");
    ::close(fd);
    return false;
  }
  if (static_cast<uint64_t>(st.st_size) > maxBytes) {
    error = "cannot read '" + path + "': " + std::to_string(st.st_size) +
            " bytes, more than the limit of " + std::to_string(maxBytes);
    ::close(fd);
    return false;
  }
  // Read at most maxBytes + 1 whatever st_size says (files in /proc report 0 and grow).
  std::string text;
  char chunk[65536];
  while (text.size() <= maxBytes) {
    size_t want = std::min(sizeof chunk, maxBytes + 1 - text.size());
    ssize_t n = ::read(fd, chunk, want);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      error = "cannot read '" + path + "': " + std::strerror(errno);
      ::close(fd);
      return false;
    }
    if (n == 0) break;
    text.append(chunk, static_cast<size_t>(n));
  }
  ::close(fd);
  if (text.size() > maxBytes) {
    error =
        "cannot read '" + path + "': more than the limit of " + std::to_string(maxBytes) + " bytes";
    return false;
  }
  out = std::move(text);
  return true;
}

} // namespace lj::io
