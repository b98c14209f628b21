// Symbol table of a program: names that stand for addresses in operands (docs/plc-dit.md
// "Symbols"). Dialect-neutral: each dialect gives its limits and address syntax as SymbolRules
// (HNC-8: frontends/hnc8/Address.h, filled by the plc.dit reader or a symbols file; FANUC:
// frontends/fanuc/FrontEnd.h, filled from a mnemonic file's %@2-E section, docs/fanuc-pmc.md
// "Symbols and comments").
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
  /// A table without rules yet: it holds no symbols and add() refuses until a table with a
  /// dialect's rules is assigned to it.
  SymbolTable() = default;
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

  /// The name as a message may show it: printable ASCII kept, other bytes as `\xNN`.
  static std::string quote(std::string_view text);

private:
  static std::string key(std::string_view name);
  const SymbolRules *rules_ = nullptr;
  std::vector<Symbol> list_;
  std::unordered_map<std::string, size_t> index_; ///< folded name -> position in list_
};

} // namespace lj
