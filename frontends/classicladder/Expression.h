// ClassicLadder's arithmetic expressions (arithmetic_expressions.csv) as a tree, parsed with the
// rules of its recursive-descent evaluator `arithm_eval.c` in LinuxCNC 2.9 (docs/classicladder.md
// "Expressions"): 32-bit wrapping int, `|` < `&` < `+ -` < `* / %` < `^` (a^(2^b), right-
// recursive), terms `( )`, decimal, `$hex`, `-constant`, `!term`, functions on variable lists,
// `@type/num@` variables; parsing stops at the first character that cannot continue (a space),
// and ClassicLadder ignores the rest without a word, which the tree records as `ignored`.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lj::classicladder {

/// A variable reference `@type/num@` or `@type/num[itype/inum]@` (index: master only).
struct VarRef {
  int32_t type = -1;
  int32_t num = 0;
  int32_t indexType = -1; ///< -1: no index
  int32_t indexNum = 0;
  bool operator==(const VarRef &o) const {
    return type == o.type && num == o.num && indexType == o.indexType && indexNum == o.indexNum;
  }
};

/// One node of an expression tree.
struct ExprNode {
  enum class Kind : uint8_t {
    Const,
    Var,
    Not, ///< `!term`: 0 -> 1, else 0
    Or,
    Xor, ///< kept for completeness: the 2.9 grammar cannot reach it
    And,
    Add,
    Sub,
    Mul,
    Div, ///< C truncation; by zero: the left operand is kept (2.9)
    Mod,
    Pow, ///< a^b = a^(2^b): `pow_int` squares a b times
    Abs,
    Mini,
    Maxi,
    Avg, ///< MOY / AVG
    // 0.9 only (model only: LinuxCNC has none of them)
    Power, ///< POW(a,b): a to the power b
    Shl,
    Shr,
    Rol,
    Ror,
  };
  Kind kind = Kind::Const;
  int32_t value = 0;                           ///< Const
  VarRef var;                                  ///< Var
  std::vector<std::unique_ptr<ExprNode>> kids; ///< operands; function arguments
};

/// A whole expression slot: a compare (`L op R`), an operate (`@var@:=expr`) or nothing (empty
/// or `#...`). The text alone does not say which; the cell that uses the slot does, so both
/// readings are parsed and the block picks one (a slot may even be used both ways).
struct Expression {
  enum class CmpOp : uint8_t { Gt, Lt, Ne, Eq, Ge, Le };
  std::string text;  ///< as stored (at most 49 characters: char[50])
  bool empty = true; ///< empty or starting with `#`: does nothing, a compare is false

  // Compare reading: the text cut at the first `<`, `>` or `=`.
  bool isCompare = false;
  CmpOp cmp = CmpOp::Eq;
  std::unique_ptr<ExprNode> left, right;

  // Operate reading: `@var@` then `:=` or `=`, then the value.
  bool isOperate = false;
  VarRef target;
  std::unique_ptr<ExprNode> value;

  /// Text ClassicLadder silently ignores (after a space, a second comparison, ...), with the
  /// 0-based offset where it starts; empty when the whole text was used.
  std::string ignored;
  int32_t ignoredAt = -1;
};

/// A syntax error of an expression: the 0-based offset in the text and what is wrong.
struct ExprError {
  int32_t offset = 0;
  std::string message;
};

/// Which grammar: LinuxCNC 2.9 (`^` is the power) or upstream 0.9 (`^` removed; POW, SHL, SHR,
/// ROL, ROR functions). 0.9 expressions are parsed for the model only.
enum class ExprDialect : uint8_t { LinuxCnc29, Upstream09 };

/// Parses `text` (already cut to 49 characters) both as a compare and as an operate. Returns
/// false with `err` when a reading that the text asks for (it has a comparison operator, or it
/// starts with `@var@=`) has a syntax error ClassicLadder would report at run time.
bool parseExpression(const std::string &text, ExprDialect dialect, Expression &out, ExprError &err);

/// Evaluates a value tree with the 2.9 semantics (32-bit wrap, division by zero keeps the left
/// operand, a^(2^b)); `read` gives a variable's value.
int32_t evaluate(const ExprNode &node, const std::function<int32_t(const VarRef &)> &read);
/// The compare reading's result (false when the slot is empty or not a compare).
bool evaluateCompare(const Expression &e, const std::function<int32_t(const VarRef &)> &read);

/// The tree as text, fully parenthesized (`(+ 1 @200/0@)`), for tests and dumps.
std::string toString(const ExprNode &node);

} // namespace lj::classicladder
