// The line tokenizer of the line-oriented front ends (HNC-8 STL, FANUC mnemonics): blank-
// separated words and a `;` or `//` comment to the end of the line.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace lj::frontend {

/// One blank-separated word of a line and its 1-based column (saturating at INT32_MAX).
struct Word {
  std::string_view text;
  int32_t col = 0;
};

/// Splits one line (without its newline) into `words` (cleared first); a `;` or `//` comment
/// goes to `comment` (text after the marker, blanks around it dropped; `hasComment` tells an
/// empty one apart; `comment` is empty without one). Blanks: space, tab, CR, VT, FF.
void splitLine(std::string_view line, std::vector<Word> &words, std::string_view &comment,
               bool &hasComment);

} // namespace lj::frontend
