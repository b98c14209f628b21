// ClassicLadder expressions: the grammar of arithm_eval.c (LinuxCNC 2.9) as a tree, and its
// evaluation with the 2.9 results the reference measured (docs/classicladder.md "Expressions").
#include "frontends/classicladder/Expression.h"

#include <climits>
#include <cstring>

namespace lj::classicladder {

namespace {

using Kind = ExprNode::Kind;

std::unique_ptr<ExprNode> node(Kind k) {
  auto n = std::make_unique<ExprNode>();
  n->kind = k;
  return n;
}

std::unique_ptr<ExprNode> binary(Kind k, std::unique_ptr<ExprNode> a, std::unique_ptr<ExprNode> b) {
  auto n = node(k);
  n->kids.push_back(std::move(a));
  n->kids.push_back(std::move(b));
  return n;
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isUpper(char c) { return c >= 'A' && c <= 'Z'; }
int hexDigit(char c) {
  if (isDigit(c)) return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// One recursive-descent pass over `s` from `pos`; stops at the first character that cannot
/// continue the expression (ClassicLadder's silent cut), or fails with a syntax error.
class Parser {
public:
  Parser(const std::string &s, size_t begin, size_t end, ExprDialect d)
      : s_(s), pos_(begin), end_(end), dialect_(d) {}

  std::unique_ptr<ExprNode> parse() { return orLevel(); }
  size_t pos() const { return pos_; }
  bool failed() const { return failed_; }
  const ExprError &error() const { return err_; }

  /// `@type/num@` or `@type/num[itype/inum]@` at the current position.
  bool variable(VarRef &v) {
    if (peek() != '@') return fail("expected a variable '@type/num@'");
    ++pos_;
    if (!number(v.type) || !expect('/') || !number(v.num)) return false;
    if (peek() == '[') {
      ++pos_;
      if (!number(v.indexType) || !expect('/') || !number(v.indexNum) || !expect(']')) return false;
    }
    return expect('@');
  }

private:
  char peek() const { return pos_ < end_ ? s_[pos_] : '\0'; }

  bool fail(const std::string &msg) {
    if (!failed_) err_ = {static_cast<int32_t>(pos_), msg};
    failed_ = true;
    return false;
  }
  bool expect(char c) {
    if (peek() == c) {
      ++pos_;
      return true;
    }
    return fail(std::string("expected '") + c + "'");
  }
  bool number(int32_t &out) {
    if (!isDigit(peek())) return fail("expected a number");
    uint32_t v = 0;
    while (isDigit(peek())) {
      v = v * 10u + static_cast<uint32_t>(peek() - '0');
      if (v > 99999999u) return fail("number too large");
      ++pos_;
    }
    out = static_cast<int32_t>(v);
    return true;
  }

  std::unique_ptr<ExprNode> orLevel() {
    auto l = xorLevel();
    while (!failed_ && peek() == '|') {
      ++pos_;
      l = binary(Kind::Or, std::move(l), xorLevel());
    }
    return l;
  }
  // In 2.9 the power level below takes every '^', so this loop never runs; 0.9 removed the
  // power and '^' is read here as XOR.
  std::unique_ptr<ExprNode> xorLevel() {
    auto l = andLevel();
    while (!failed_ && peek() == '^' && dialect_ == ExprDialect::Upstream09) {
      ++pos_;
      l = binary(Kind::Xor, std::move(l), andLevel());
    }
    return l;
  }
  std::unique_ptr<ExprNode> andLevel() {
    auto l = addLevel();
    while (!failed_ && peek() == '&') {
      ++pos_;
      l = binary(Kind::And, std::move(l), addLevel());
    }
    return l;
  }
  std::unique_ptr<ExprNode> addLevel() {
    auto l = mulLevel();
    while (!failed_ && (peek() == '+' || peek() == '-')) {
      Kind k = peek() == '+' ? Kind::Add : Kind::Sub;
      ++pos_;
      l = binary(k, std::move(l), mulLevel());
    }
    return l;
  }
  std::unique_ptr<ExprNode> mulLevel() {
    auto l = powLevel();
    while (!failed_ && (peek() == '*' || peek() == '/' || peek() == '%')) {
      Kind k = peek() == '*' ? Kind::Mul : peek() == '/' ? Kind::Div : Kind::Mod;
      ++pos_;
      l = binary(k, std::move(l), powLevel());
    }
    return l;
  }
  std::unique_ptr<ExprNode> powLevel() {
    auto t = term();
    if (!failed_ && peek() == '^' && dialect_ == ExprDialect::LinuxCnc29) {
      ++pos_;
      return binary(Kind::Pow, std::move(t), powLevel());
    }
    return t;
  }

  std::unique_ptr<ExprNode> constant() {
    auto n = node(Kind::Const);
    uint32_t v = 0;
    if (peek() == '$') {
      ++pos_;
      if (hexDigit(peek()) < 0) {
        fail("expected a hexadecimal digit after '$'");
        return n;
      }
      while (hexDigit(peek()) >= 0) v = v * 16u + static_cast<uint32_t>(hexDigit(s_[pos_++]));
    } else {
      bool neg = false;
      if (peek() == '-') {
        neg = true;
        ++pos_;
      }
      // `-@var@` is 0 in 2.9 (unary minus takes constants only); the rest is then cut.
      while (isDigit(peek())) v = v * 10u + static_cast<uint32_t>(s_[pos_++] - '0');
      if (neg) v = 0u - v;
    }
    n->value = static_cast<int32_t>(v);
    return n;
  }

  std::unique_ptr<ExprNode> function() {
    size_t at = pos_;
    std::string name;
    while (isUpper(peek())) name += s_[pos_++];
    Kind k;
    bool one = false;
    if (name == "ABS") {
      k = Kind::Abs;
      one = true;
    } else if (name == "MINI") {
      k = Kind::Mini;
    } else if (name == "MAXI") {
      k = Kind::Maxi;
    } else if (name == "MOY" || name == "AVG") {
      k = Kind::Avg;
    } else if (dialect_ == ExprDialect::Upstream09 &&
               (name == "POW" || name == "SHL" || name == "SHR" || name == "ROL" ||
                name == "ROR")) {
      // 0.9: two arguments, each an expression
      k = name == "POW"   ? Kind::Power
          : name == "SHL" ? Kind::Shl
          : name == "SHR" ? Kind::Shr
          : name == "ROL" ? Kind::Rol
                          : Kind::Ror;
      auto n = node(k);
      if (!expect('(')) return n;
      n->kids.push_back(orLevel());
      if (failed_ || !expect(',')) return n;
      n->kids.push_back(orLevel());
      if (!failed_) expect(')');
      return n;
    } else {
      pos_ = at;
      fail("unknown function '" + name + "'");
      return node(Kind::Const);
    }
    auto n = node(k);
    if (!expect('(')) return n;
    for (;;) {
      auto v = node(Kind::Var);
      if (!variable(v->var)) return n;
      n->kids.push_back(std::move(v));
      if (peek() == ',' && !one) {
        ++pos_;
        continue;
      }
      break;
    }
    expect(')');
    return n;
  }

  std::unique_ptr<ExprNode> term() {
    char c = peek();
    if (c == '(') {
      ++pos_;
      auto e = orLevel();
      if (!failed_) expect(')');
      return e;
    }
    if (isDigit(c) || c == '-' || c == '$') return constant();
    if (c == '@') {
      auto v = node(Kind::Var);
      variable(v->var);
      return v;
    }
    if (isUpper(c)) return function();
    if (c == '!') {
      ++pos_;
      auto n = node(Kind::Not);
      n->kids.push_back(term());
      return n;
    }
    fail(c == '\0' ? "the expression ends where a value is expected"
                   : std::string("'") + c + "' where a value is expected");
    return node(Kind::Const);
  }

  const std::string &s_;
  size_t pos_, end_;
  ExprDialect dialect_;
  bool failed_ = false;
  ExprError err_;
};

void noteIgnored(Expression &out, const std::string &text, size_t from, size_t to) {
  if (from >= to || !out.ignored.empty()) return;
  out.ignored = text.substr(from, to - from);
  out.ignoredAt = static_cast<int32_t>(from);
}

} // namespace

bool parseExpression(const std::string &text, ExprDialect dialect, Expression &out,
                     ExprError &err) {
  out = Expression();
  out.text = text;
  if (text.empty() || text[0] == '#') return true;
  out.empty = false;

  // Compare: cut at the first '<', '>' or '='; a second '=' or '>' belongs to the operator.
  ExprError cmpErr;
  bool cmpAsked = false;
  size_t op = text.find_first_of("<>=");
  if (op != std::string::npos) {
    cmpAsked = true;
    char a = text[op];
    char b = op + 1 < text.size() ? text[op + 1] : '\0';
    size_t rhs = op + 1;
    Expression::CmpOp cmp = a == '<'   ? Expression::CmpOp::Lt
                            : a == '>' ? Expression::CmpOp::Gt
                                       : Expression::CmpOp::Eq;
    if (b == '=' || b == '>') {
      rhs = op + 2;
      if (a == '<')
        cmp = b == '=' ? Expression::CmpOp::Le : Expression::CmpOp::Ne;
      else if (a == '>')
        cmp = b == '=' ? Expression::CmpOp::Ge : Expression::CmpOp::Gt;
      // "==" and "=>" both mean "="
    }
    Parser l(text, 0, op, dialect);
    auto left = l.parse();
    if (!l.failed()) {
      Parser r(text, rhs, text.size(), dialect);
      auto right = r.parse();
      if (!r.failed()) {
        out.isCompare = true;
        out.cmp = cmp;
        out.left = std::move(left);
        out.right = std::move(right);
        noteIgnored(out, text, l.pos(), op);
        noteIgnored(out, text, r.pos(), text.size());
      } else {
        cmpErr = r.error();
      }
    } else {
      cmpErr = l.error();
    }
  }

  // Operate: `@var@` then ":=" or "=".
  ExprError opErr;
  bool opAsked = false;
  if (text[0] == '@') {
    Parser t(text, 0, text.size(), dialect);
    VarRef target;
    if (t.variable(target)) {
      size_t p = t.pos();
      size_t vstart = 0;
      if (text.compare(p, 2, ":=") == 0)
        vstart = p + 2;
      else if (p < text.size() && text[p] == '=')
        vstart = p + 1;
      if (vstart) {
        opAsked = true;
        Parser v(text, vstart, text.size(), dialect);
        auto value = v.parse();
        if (!v.failed()) {
          out.isOperate = true;
          out.target = target;
          out.value = std::move(value);
          if (out.isCompare) {
            out.ignored.clear(); // the operate reading's cut is the one that matters
            out.ignoredAt = -1;
          }
          noteIgnored(out, text, v.pos(), text.size());
        } else {
          opErr = v.error();
        }
      }
    }
  }

  if (out.isCompare || out.isOperate) return true;
  if (opAsked)
    err = opErr;
  else if (cmpAsked)
    err = cmpErr;
  else
    err = {0, "neither a comparison ('<', '>', '=', ...) nor an assignment '@var@:=...'"};
  return false;
}

namespace {

uint32_t u(int32_t v) { return static_cast<uint32_t>(v); }
int32_t s(uint32_t v) { return static_cast<int32_t>(v); }

} // namespace

int32_t evaluate(const ExprNode &n, const std::function<int32_t(const VarRef &)> &read) {
  auto arg = [&](size_t i) { return evaluate(*n.kids[i], read); };
  switch (n.kind) {
  case Kind::Const:
    return n.value;
  case Kind::Var:
    return read(n.var);
  case Kind::Not:
    return arg(0) == 0 ? 1 : 0;
  case Kind::Or:
    return arg(0) | arg(1);
  case Kind::Xor:
    return arg(0) ^ arg(1);
  case Kind::And:
    return arg(0) & arg(1);
  case Kind::Add:
    return s(u(arg(0)) + u(arg(1)));
  case Kind::Sub:
    return s(u(arg(0)) - u(arg(1)));
  case Kind::Mul:
    return s(u(arg(0)) * u(arg(1)));
  case Kind::Div:
  case Kind::Mod: {
    int32_t a = arg(0), b = arg(1);
    if (b == 0) return a; // 2.9: the operation is skipped, the left operand kept
    if (a == INT32_MIN && b == -1) return n.kind == Kind::Div ? INT32_MIN : 0;
    return n.kind == Kind::Div ? a / b : a % b;
  }
  case Kind::Pow: {
    uint32_t r = u(arg(0));
    int32_t b = arg(1);
    // pow_int squares b times; modulo 2^32 the squares reach their fixed point (0 for an even
    // base, 1 for an odd one) after at most 32 squarings, so 40 rounds give the same result.
    for (int32_t i = 0; i < b && i < 40; ++i) r = r * r;
    return s(r);
  }
  case Kind::Abs: {
    int32_t a = arg(0);
    return a < 0 ? s(0u - u(a)) : a;
  }
  case Kind::Mini:
  case Kind::Maxi:
  case Kind::Avg: {
    int32_t m = n.kind == Kind::Mini ? INT32_MAX : INT32_MIN;
    uint32_t sum = 0;
    for (size_t i = 0; i < n.kids.size(); ++i) {
      int32_t v = arg(i);
      if (n.kind == Kind::Mini && v < m) m = v;
      if (n.kind == Kind::Maxi && v > m) m = v;
      sum += u(v);
    }
    if (n.kind != Kind::Avg) return m;
    return n.kids.empty() ? 0 : s(sum) / static_cast<int32_t>(n.kids.size());
  }
  case Kind::Power: {
    uint32_t r = 1, a = u(arg(0));
    for (int32_t i = 0, b = arg(1); i < b && i < 64; ++i) r *= a;
    return s(r);
  }
  case Kind::Shl:
  case Kind::Shr:
  case Kind::Rol:
  case Kind::Ror: {
    uint32_t a = u(arg(0)), b = u(arg(1)) & 31u;
    switch (n.kind) {
    case Kind::Shl:
      return s(a << b);
    case Kind::Shr:
      return s(a >> b);
    case Kind::Rol:
      return s(b ? (a << b) | (a >> (32u - b)) : a);
    default:
      return s(b ? (a >> b) | (a << (32u - b)) : a);
    }
  }
  }
  return 0;
}

bool evaluateCompare(const Expression &e, const std::function<int32_t(const VarRef &)> &read) {
  if (e.empty || !e.isCompare) return false;
  int32_t l = evaluate(*e.left, read), r = evaluate(*e.right, read);
  switch (e.cmp) {
  case Expression::CmpOp::Gt:
    return l > r;
  case Expression::CmpOp::Lt:
    return l < r;
  case Expression::CmpOp::Ne:
    return l != r;
  case Expression::CmpOp::Eq:
    return l == r;
  case Expression::CmpOp::Ge:
    return l >= r;
  case Expression::CmpOp::Le:
    return l <= r;
  }
  return false;
}

std::string toString(const ExprNode &n) {
  static const char *names[] = {"",     "",    "!",   "|",   "^x",  "&",   "+",
                                "-",    "*",   "/",   "%",   "^",   "ABS", "MINI",
                                "MAXI", "AVG", "POW", "SHL", "SHR", "ROL", "ROR"};
  if (n.kind == Kind::Const) return std::to_string(n.value);
  if (n.kind == Kind::Var) {
    std::string v = "@" + std::to_string(n.var.type) + "/" + std::to_string(n.var.num);
    if (n.var.indexType >= 0)
      v += "[" + std::to_string(n.var.indexType) + "/" + std::to_string(n.var.indexNum) + "]";
    return v + "@";
  }
  std::string out = std::string("(") + names[static_cast<int>(n.kind)];
  for (const auto &k : n.kids) out += " " + toString(*k);
  return out + ")";
}

} // namespace lj::classicladder
