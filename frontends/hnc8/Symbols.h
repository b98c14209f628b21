// Symbol table of a program: names that stand for addresses in operands (docs/plc-dit.md
// "Symbols"). Built by the plc.dit reader or a symbols file and read by the HNC-8 parser; the
// FANUC front end builds one with its own rules (SymbolRules) from a mnemonic file's %@2-E
// section (docs/fanuc-pmc.md "Symbols and comments").
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

/// What a dialect's symbol table accepts: the limits and the address check (the name syntax,
/// isNameShaped, and case-insensitive uniqueness are the same for every dialect).
struct SymbolRules {
  size_t maxSymbols;
  size_t maxNameBytes; ///< a UTF-8 CJK character takes 3
  size_t maxCommentBytes;
  const char *limitOf; ///< whose limit maxSymbols is, for "too many symbols" ("HNC-8 limit")
  /// Canonical text of an address, or empty with `error` set (without the symbol's name).
  std::string (*canonicalAddress)(std::string_view text, std::string &error);
};

/// An ordered set of symbols with case-insensitive (ASCII) unique names.
class SymbolTable {
public:
  /// HNC-8 specification: "symbol names 1000 entries".
  static constexpr size_t kMaxSymbols = 1000;
  /// Longest HNC-8 name in bytes (a UTF-8 CJK character takes 3).
  static constexpr size_t kMaxNameBytes = 64;
  /// Longest HNC-8 comment in bytes.
  static constexpr size_t kMaxCommentBytes = 256;

  /// The HNC-8 rules (the limits above, canonicalAddress below).
  static const SymbolRules &hnc8Rules();

  /// A table with the HNC-8 rules.
  SymbolTable() : rules_(&hnc8Rules()) {}
  /// A table with a dialect's rules (`rules` must outlive the table).
  explicit SymbolTable(const SymbolRules &rules) : rules_(&rules) {}

  /// The part of a symbol a failed add() is about (a reader locates the error there).
  enum class Field : uint8_t { Name, Address, Comment };

  /// Validate and append a symbol (address normalized to canonical text, blanks around the
  /// comment dropped) under the table's rules. On failure returns false, sets `error` (without
  /// a location) naming the problem and, when given, `failed` to the field it is about.
  bool add(std::string_view name, std::string_view address, std::string_view comment,
           std::string &error, Field *failed = nullptr);

  /// The symbol named `name` (case-insensitive for ASCII letters), or nullptr.
  const Symbol *find(std::string_view name) const;

  const std::vector<Symbol> &symbols() const { return list_; }
  size_t size() const { return list_.size(); }
  bool empty() const { return list_.empty(); }

  /// Whether `token` has the shape of a symbol name: first byte a letter, `_` or non-ASCII;
  /// the rest letters, digits, `_` or non-ASCII; not a letter followed only by digits (that is
  /// an address such as `X10` or `L3`). Length is not checked here.
  static bool isNameShaped(std::string_view token);

  /// Canonical text of an HNC-8 operand address (`x010.3` -> `X10.3`), or empty with `error` set
  /// when `text` is not a valid address (area letter, index range, bit number).
  static std::string canonicalAddress(std::string_view text, std::string &error);

  /// The name as a message may show it: printable ASCII kept, other bytes as `\xNN`.
  static std::string quote(std::string_view text);

private:
  static std::string key(std::string_view name);
  const SymbolRules *rules_;
  std::vector<Symbol> list_;
  std::unordered_map<std::string, size_t> index_; ///< folded name -> position in list_
};

} // namespace lj
