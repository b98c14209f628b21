// Symbol names and their addresses: name syntax, the dialect's address check and
// case-insensitive lookup (docs/plc-dit.md "Symbols").
#include "ir/SymbolTable.h"

#include "ir/Diagnostics.h"

namespace lj {

namespace {

bool isAsciiLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isHigh(char c) { return static_cast<unsigned char>(c) >= 0x80; }

} // namespace

std::string SymbolTable::quote(std::string_view text) {
  // Non-ASCII bytes are kept: symbol names are often Chinese (UTF-8).
  return quoteToken(text, 80, /*keepNonAscii=*/true);
}

bool SymbolTable::isNameShaped(std::string_view t) {
  if (t.empty()) return false;
  if (!isAsciiLetter(t[0]) && t[0] != '_' && !isHigh(t[0])) return false;
  bool allDigitsAfterFirst = t.size() > 1;
  for (size_t i = 1; i < t.size(); ++i) {
    char c = t[i];
    if (!isAsciiLetter(c) && !isDigit(c) && c != '_' && !isHigh(c)) return false;
    allDigitsAfterFirst = allDigitsAfterFirst && isDigit(c);
  }
  // `X10`, `L3`, `Q7`: an address (or a mistyped one), never a name.
  return !(isAsciiLetter(t[0]) && allDigitsAfterFirst);
}

std::string SymbolTable::key(std::string_view name) {
  std::string k(name);
  for (char &c : k)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return k;
}

bool SymbolTable::add(std::string_view name, std::string_view address, std::string_view comment,
                      std::string &error, Field *failed) {
  Field scratch;
  Field &field = failed ? *failed : scratch;
  field = Field::Name;
  if (!rules_) {
    error = "symbol " + quote(name) + ": the table has no dialect rules";
    return false;
  }
  if (name.size() > rules_->maxNameBytes) {
    error = "symbol name " + quote(name) + " is longer than " +
            std::to_string(rules_->maxNameBytes) + " bytes";
    return false;
  }
  if (!isNameShaped(name)) {
    error = "bad symbol name " + quote(name) +
            ": a name starts with a letter, '_' or a non-ASCII character, continues with "
            "letters, digits, '_' or non-ASCII characters, and is not an address like X10";
    return false;
  }
  std::string canon = rules_->canonicalAddress(address, error);
  if (canon.empty()) {
    field = Field::Address;
    error = "symbol " + quote(name) + ": " + error;
    return false;
  }
  // Blanks around a comment are layout, not content (the container trims them when reading).
  while (!comment.empty() && (comment.front() == ' ' || comment.front() == '\t'))
    comment.remove_prefix(1);
  while (!comment.empty() && (comment.back() == ' ' || comment.back() == '\t'))
    comment.remove_suffix(1);
  field = Field::Comment;
  if (comment.size() > rules_->maxCommentBytes) {
    error = "symbol " + quote(name) + ": comment longer than " +
            std::to_string(rules_->maxCommentBytes) + " bytes";
    return false;
  }
  for (char c : comment) {
    auto u = static_cast<unsigned char>(c);
    if ((u < 0x20 && c != '\t') || u == 0x7f) {
      error = "symbol " + quote(name) + ": control character in comment";
      return false;
    }
  }
  field = Field::Name;
  std::string k = key(name);
  if (auto it = index_.find(k); it != index_.end()) {
    error = "duplicate symbol " + quote(name) + " (already defined as " +
            quote(list_[it->second].name) + "; names are case-insensitive)";
    return false;
  }
  if (list_.size() >= rules_->maxSymbols) {
    error = "too many symbols: at most " + std::to_string(rules_->maxSymbols) + " (" +
            rules_->limitOf + ")";
    return false;
  }
  index_.emplace(std::move(k), list_.size());
  list_.push_back({std::string(name), std::move(canon), std::string(comment)});
  return true;
}

const Symbol *SymbolTable::find(std::string_view name) const {
  auto it = index_.find(key(name));
  return it == index_.end() ? nullptr : &list_[it->second];
}

} // namespace lj
