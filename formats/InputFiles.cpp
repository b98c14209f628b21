// Stimulus and parameter file parsers: line-oriented, located errors, no exceptions.
#include "formats/InputFiles.h"

#include "ir/Profile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>

namespace lj::formats {

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
                                      std::string &error, ItemParser assign) {
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

std::optional<std::vector<Assignment>> parseParams(std::string_view text, const std::string &file,
                                                   std::string &error, const TargetProfile *tp) {
  if (!tp || tp->systemParams.counterFormat == 0) return parseParams(text, file, error);
  struct Value {
    Assignment a;
    int32_t line, col;
  };
  std::vector<Value> values;
  std::optional<Assignment> type;
  auto up = [](std::string_view v) {
    std::string u(v);
    for (char &c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return u;
  };
  bool ok = forEachLine(text, [&](int32_t lineNo, std::string_view line) {
    size_t k = 0;
    while (k < line.size() && isBlank(line[k])) ++k;
    if (k == line.size()) return true;
    auto at = [&](size_t pos) {
      return file + ":" + std::to_string(lineNo) + ":" + std::to_string(pos + 1) + ": ";
    };
    const size_t eq = line.find('=');
    size_t v = eq == std::string_view::npos ? line.size() : eq + 1;
    while (v < line.size() && isBlank(line[v])) ++v;
    std::string compact;
    for (char c : line)
      if (!isBlank(c)) compact.push_back(c);
    const std::string key = up(compact.substr(0, compact.find('=')));
    if (key == "COUNTER") {
      const std::string val = up(compact.substr(compact.find('=') + 1));
      if (eq == std::string_view::npos || (val != "BCD" && val != "BINARY")) {
        error = at(v) + "the counter data type is BCD or BINARY, got '" +
                std::string(line.substr(v)) + "' (COUNTER = BCD or COUNTER = BINARY)";
        return false;
      }
      CliAddress a;
      a.area = Area::None;
      a.index = static_cast<int32_t>(tp->systemParams.counterFormat);
      a.profile = tp;
      a.width = 1;
      a.text = "COUNTER";
      type =
          Assignment{a, val == "BCD" ? TargetProfile::kCounterBcd : TargetProfile::kCounterBinary};
      return true;
    }
    std::string why;
    std::optional<Assignment> a = parseProfileAssignment(*tp, compact, why);
    if (!a) {
      error = at(k) + why + " (expected COUNTER = BCD|BINARY or a PMC parameter ADDR = VALUE)";
      return false;
    }
    const Area pa = a->addr.area;
    if (pa != Area::TimerData && pa != Area::CounterData && pa != Area::KeepRelay &&
        pa != Area::DataTable) {
      error = at(k) + "'" + a->addr.text + "' is not a PMC parameter (areas T, C, K, D)";
      return false;
    }
    values.push_back({std::move(*a), lineNo, static_cast<int32_t>(v)});
    return true;
  });
  if (!ok) return std::nullopt;
  std::vector<Assignment> out;
  const bool bcd = type && type->value == TargetProfile::kCounterBcd;
  if (type) out.push_back(*type);
  const AreaInfo &c = tp->area(Area::CounterData);
  for (Value &x : values) {
    CliAddress &a = x.a.addr;
    // CTR's presets and counts (C0.., reference 6.4) are BCD when the data type is: the screen
    // shows decimal [L1971-L1973], so the value is written as its decimal digits.
    if (bcd && a.area == Area::CounterData && a.index < c.count && !a.isBit()) {
      const int digits = 2 * (a.width ? a.width : c.bytes);
      int64_t lim = 1;
      for (int d = 0; d < digits; ++d) lim *= 10;
      if (x.a.value < 0 || x.a.value >= lim) {
        error = file + ":" + std::to_string(x.line) + ":" + std::to_string(x.col + 1) +
                ": counter value " + std::to_string(x.a.value) + " of " + a.text +
                " is not BCD: the counter data type is BCD and " + a.text + " holds " +
                std::to_string(digits) + " digits (0.." + std::to_string(lim - 1) + ")";
        return std::nullopt;
      }
      int64_t bcdValue = 0;
      for (int d = 0; d < digits; ++d) {
        bcdValue |= (x.a.value % 10) << (4 * d);
        x.a.value /= 10;
      }
      x.a.value = bcdValue;
    }
    out.push_back(std::move(x.a));
  }
  return out;
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

} // namespace lj::formats
