// ClassicLadder expressions: parse and evaluate with the LinuxCNC 2.9 results the reference
// measured with classicladder_rt (../shared/reference/classicladder.md 4.8 and 5).
#include "frontends/classicladder/Expression.h"

#include <climits>
#include <gtest/gtest.h>
#include <map>

using namespace lj::classicladder;

namespace {

std::map<std::pair<int, int>, int32_t> vars;
int32_t readVar(const VarRef &v) {
  auto it = vars.find({v.type, v.num});
  return it == vars.end() ? 0 : it->second;
}

/// The operate reading's value of `@200/0@:=<value>`.
int32_t calc(const std::string &value, std::string *ignored = nullptr) {
  Expression e;
  ExprError err;
  EXPECT_TRUE(parseExpression("@200/0@:=" + value, ExprDialect::LinuxCnc29, e, err))
      << value << ": " << err.message;
  if (!e.isOperate) return INT32_MIN + 12345;
  if (ignored) *ignored = e.ignored;
  return evaluate(*e.value, readVar);
}

bool compare(const std::string &text) {
  Expression e;
  ExprError err;
  EXPECT_TRUE(parseExpression(text, ExprDialect::LinuxCnc29, e, err))
      << text << ": " << err.message;
  return evaluateCompare(e, readVar);
}

} // namespace

TEST(ClExpression, CaretIsRepeatedSquaring) {
  EXPECT_EQ(calc("3^2"), 81); // measured 3^2 = 81
  EXPECT_EQ(calc("2^3"), 256);
  EXPECT_EQ(calc("5^1"), 25);
  // Right-recursive: 2^(2^1) = 2^4 = 2 squared four times = 65536 ((2^2)^1 would be 256).
  EXPECT_EQ(calc("2^2^1"), 65536);
}

TEST(ClExpression, IntegerRules) {
  EXPECT_EQ(calc("-7/2"), -3);
  EXPECT_EQ(calc("-7%3"), -1);
  EXPECT_EQ(calc("5%0+1"), 6); // 2.9 skips a division by zero, keeping the left operand
  EXPECT_EQ(calc("5/0"), 5);
  EXPECT_EQ(calc("2147483647+1"), INT_MIN); // wraps
  EXPECT_EQ(calc("$FF"), 255);
  EXPECT_EQ(calc("1+2*3"), 7);
  EXPECT_EQ(calc("(1+2)*3"), 9);
  EXPECT_EQ(calc("6|1&3"), 7); // & binds tighter than |
  EXPECT_EQ(calc("!0"), 1);
  EXPECT_EQ(calc("!5"), 0);
  EXPECT_EQ(calc("5/2"), 2);
}

TEST(ClExpression, CutAtSpaceAndUnaryMinusOnConstantsOnly) {
  std::string ign;
  EXPECT_EQ(calc("1 +2", &ign), 1); // measured: "1 +2" gives 1
  EXPECT_EQ(ign, " +2");
  vars[{270, 0}] = 9;
  EXPECT_EQ(calc("-@270/0@", &ign), 0); // measured: -@v@ gives 0, the rest ignored
  EXPECT_EQ(ign, "@270/0@");
  EXPECT_EQ(calc("-5+1"), -4);
  vars.clear();
}

TEST(ClExpression, Functions) {
  vars[{200, 1}] = -4;
  vars[{200, 2}] = 10;
  vars[{200, 3}] = 3;
  EXPECT_EQ(calc("ABS(@200/1@)"), 4);
  EXPECT_EQ(calc("MINI(@200/1@,@200/2@,@200/3@)"), -4);
  EXPECT_EQ(calc("MAXI(@200/1@,@200/2@,@200/3@)"), 10);
  EXPECT_EQ(calc("MOY(@200/2@,@200/3@)"), 6);
  EXPECT_EQ(calc("AVG(@200/2@,@200/3@)"), 6);
  vars.clear();
}

TEST(ClExpression, CompareRules) {
  EXPECT_TRUE(compare("2=2,&1<0")); // measured: only the first comparison counts
  vars[{270, 0}] = 7;
  EXPECT_FALSE(compare("@270/0@!=5")); // measured: '!=' is '='
  EXPECT_TRUE(compare("@270/0@<>5"));
  EXPECT_TRUE(compare("@270/0@>=7"));
  EXPECT_TRUE(compare("@270/0@<=7"));
  EXPECT_FALSE(compare("@270/0@<7"));
  EXPECT_TRUE(compare("@270/0@==7"));
  EXPECT_TRUE(compare("@270/0@=>7")); // "=>" means "="
  vars[{200, 1}] = 2;
  EXPECT_TRUE(compare("(@270/0@-1)&3=@200/1@")); // 924.clp: (7-1)&3 = 2
  vars.clear();
}

TEST(ClExpression, OperateForms) {
  Expression e;
  ExprError err;
  ASSERT_TRUE(parseExpression("@200/0@:=@200/0@+1", ExprDialect::LinuxCnc29, e, err));
  EXPECT_TRUE(e.isOperate);
  EXPECT_EQ(e.target.type, 200);
  EXPECT_EQ(toString(*e.value), "(+ @200/0@ 1)");
  ASSERT_TRUE(parseExpression("@280/2@=1", ExprDialect::LinuxCnc29, e, err)); // ec-sim form
  EXPECT_TRUE(e.isOperate);
  EXPECT_EQ(e.target.type, 280);
  EXPECT_EQ(e.target.num, 2);
  ASSERT_TRUE(parseExpression("@200/0[200/9]@:=1", ExprDialect::LinuxCnc29, e, err));
  EXPECT_EQ(e.target.indexType, 200);
  EXPECT_EQ(e.target.indexNum, 9);
  ASSERT_TRUE(parseExpression("", ExprDialect::LinuxCnc29, e, err));
  EXPECT_TRUE(e.empty);
  EXPECT_FALSE(evaluateCompare(e, readVar)); // an empty compare is false
  ASSERT_TRUE(parseExpression("#@200/0@:=1", ExprDialect::LinuxCnc29, e, err));
  EXPECT_TRUE(e.empty);
}

TEST(ClExpression, SyntaxErrorsAreLocated) {
  Expression e;
  ExprError err;
  EXPECT_FALSE(parseExpression("@200/0@:=FOO(@200/1@)", ExprDialect::LinuxCnc29, e, err));
  EXPECT_EQ(err.offset, 9);
  EXPECT_NE(err.message.find("FOO"), std::string::npos);
  EXPECT_FALSE(parseExpression("@200/0@:='c'", ExprDialect::LinuxCnc29, e, err)); // 2.9: error
  EXPECT_EQ(err.offset, 9);
  EXPECT_FALSE(parseExpression("@200/0@:=(1+2", ExprDialect::LinuxCnc29, e, err));
  EXPECT_FALSE(parseExpression("@200/0@:=@20x/1@", ExprDialect::LinuxCnc29, e, err));
  EXPECT_FALSE(parseExpression("@200/0@+1", ExprDialect::LinuxCnc29, e, err));
  EXPECT_FALSE(parseExpression("@200/0@:=", ExprDialect::LinuxCnc29, e, err));
}

TEST(ClExpression, Upstream09CaretIsXor) {
  Expression e;
  ExprError err;
  ASSERT_TRUE(parseExpression("@200/0@:=6^3", ExprDialect::Upstream09, e, err));
  EXPECT_EQ(evaluate(*e.value, readVar), 5);
}
