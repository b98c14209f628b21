// The shared line tokenizer (frontends/common/LineTokens.h).
#include "frontends/common/LineTokens.h"

#include <climits>

namespace lj::frontend {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

} // namespace

void splitLine(std::string_view line, std::vector<Word> &words, std::string_view &comment,
               bool &hasComment) {
  words.clear();
  hasComment = false;
  comment = {};
  size_t end = line.size();
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == ';' || (line[i] == '/' && i + 1 < line.size() && line[i + 1] == '/')) {
      end = i;
      hasComment = true;
      comment = line.substr(i + (line[i] == ';' ? 1 : 2));
      while (!comment.empty() && isSpace(comment.front())) comment.remove_prefix(1);
      while (!comment.empty() && isSpace(comment.back())) comment.remove_suffix(1);
      break;
    }
  }
  size_t i = 0;
  while (i < end) {
    while (i < end && isSpace(line[i])) ++i;
    if (i >= end) break;
    size_t start = i;
    while (i < end && !isSpace(line[i])) ++i;
    int32_t col = start >= INT32_MAX ? INT32_MAX : static_cast<int32_t>(start + 1);
    words.push_back({line.substr(start, i - start), col});
  }
}

} // namespace lj::frontend
