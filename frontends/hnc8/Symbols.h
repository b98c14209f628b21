// Symbol table of a program: names that stand for addresses in STL operands (docs/plc-dit.md
// "Symbols"). Built by the plc.dit reader or a symbols file; read by the parser.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lj {

/// One symbol: `name` stands for `address` (canonical text such as `X10.0`, `D5`, `L3`).
struct Symbol {
  std::string name;
  std::string address;
  std::string comment; ///< free text, may be empty
};

/// An ordered set of symbols with case-insensitive (ASCII) unique names.
class SymbolTable {
public:
  /// HNC-8 specification: "symbol names 1000 entries".
  static constexpr size_t kMaxSymbols = 1000;
  /// Longest name in bytes (a UTF-8 CJK character takes 3).
  static constexpr size_t kMaxNameBytes = 64;
  /// Longest comment in bytes.
  static constexpr size_t kMaxCommentBytes = 256;

  /// Validate and append a symbol (address normalized to canonical text, blanks around the
  /// comment dropped). On failure returns
  /// false and sets `error` (without a location) naming the problem.
  bool add(std::string_view name, std::string_view address, std::string_view comment,
           std::string &error);

  /// The symbol named `name` (case-insensitive for ASCII letters), or nullptr.
  const Symbol *find(std::string_view name) const;

  const std::vector<Symbol> &symbols() const { return list_; }
  size_t size() const { return list_.size(); }
  bool empty() const { return list_.empty(); }

  /// Whether `token` has the shape of a symbol name: first byte a letter, `_` or non-ASCII;
  /// the rest letters, digits, `_` or non-ASCII; not a letter followed only by digits (that is
  /// an address such as `X10` or `L3`). Length is not checked here.
  static bool isNameShaped(std::string_view token);

  /// Canonical text of an operand address (`x010.3` -> `X10.3`), or empty with `error` set when
  /// `text` is not a valid address (area letter, index range, bit number).
  static std::string canonicalAddress(std::string_view text, std::string &error);

  /// The name as a message may show it: printable ASCII kept, other bytes as `\xNN`.
  static std::string quote(std::string_view text);

private:
  static std::string key(std::string_view name);
  std::vector<Symbol> list_;
  std::unordered_map<std::string, size_t> index_; ///< folded name -> position in list_
};

} // namespace lj
