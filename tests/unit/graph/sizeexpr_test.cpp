// Size expressions: values, operators and precedence, vectors and broadcasting, floor division,
// and errors that point at the offending token.
#include "graph/sizeexpr.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace pl;
using namespace pl::graph;

namespace {

// As if written at preset.toml:7:10 (the opening quote of the TOML string).
SizeExpr text(const std::string& t) {
    SizeExpr e;
    e.text = t;
    e.loc = {"preset.toml", 7, 10};
    return e;
}

SizeEnv env() {
    SizeEnv e;
    e.view_w = 640;
    e.view_h = 360;
    e.params["taps"] = 5;
    e.params["spread"] = 2.9;
    e.params["neg"] = -2.9;
    e.params["show"] = 2;  // an enum at its third option
    e.options["show"] = {"lit", "count", "slices", "taa"};
    return e;
}

std::vector<int64_t> eval(const std::string& t) {
    auto r = eval_size(text(t), env());
    EXPECT_TRUE(r) << t << ": " << (r ? "" : r.error().format());
    return r ? *r : std::vector<int64_t>{};
}

using V = std::vector<int64_t>;

// Column of the token at `offset` in the string: quote at 10, first character at 11.
int col_of(size_t offset) { return 10 + 1 + static_cast<int>(offset); }

} // namespace

TEST(SizeExpr, NamesAndLiterals) {
    EXPECT_EQ(eval("view"), (V{640, 360}));
    EXPECT_EQ(eval("view.w"), (V{640}));
    EXPECT_EQ(eval("view.h"), (V{360}));
    EXPECT_EQ(eval("params.taps"), (V{5}));
    EXPECT_EQ(eval("  42  "), (V{42}));
    EXPECT_EQ(eval("params.spread"), (V{2}));  // floats truncate
    EXPECT_EQ(eval("params.neg"), (V{-2}));    // ... toward zero
    SizeExpr lit;
    lit.literal = {64, 32};
    EXPECT_EQ(*eval_size(lit, env()), (V{64, 32}));
}

TEST(SizeExpr, OperatorsAndPrecedence) {
    EXPECT_EQ(eval("2 + 3 * 4"), (V{14}));
    EXPECT_EQ(eval("(2 + 3) * 4"), (V{20}));
    EXPECT_EQ(eval("10 - 4 - 3"), (V{3}));    // left associative
    EXPECT_EQ(eval("100 / 10 / 5"), (V{2}));
    EXPECT_EQ(eval("7 % 4 * 2"), (V{6}));     // * / % share a level, left to right
    EXPECT_EQ(eval("2 * 3 % 4"), (V{2}));
    EXPECT_EQ(eval("1 + 7 % 4"), (V{4}));
    EXPECT_EQ(eval("-3 + 10"), (V{7}));       // unary minus binds tighter than +
    EXPECT_EQ(eval("- -3"), (V{3}));
    EXPECT_EQ(eval("-(2 + 3) * 2"), (V{-10}));
    EXPECT_EQ(eval("2 * -3"), (V{-6}));
    EXPECT_EQ(eval("+4"), (V{4}));
    EXPECT_EQ(eval("view.w*view.h*4"), (V{921600}));
    EXPECT_EQ(eval("params.taps * 2 + -1"), (V{9}));
    EXPECT_EQ(eval("((((1))))"), (V{1}));
}

TEST(SizeExpr, FloorDivisionAndModulo) {
    EXPECT_EQ(eval("7 / 2"), (V{3}));
    EXPECT_EQ(eval("-7 / 2"), (V{-4}));  // floor, not truncation
    EXPECT_EQ(eval("7 / -2"), (V{-4}));
    EXPECT_EQ(eval("-7 / -2"), (V{3}));
    EXPECT_EQ(eval("-7 % 2"), (V{1}));   // a == (a / b) * b + a % b
    EXPECT_EQ(eval("7 % -2"), (V{-1}));
    EXPECT_EQ(eval("ceil_div(7, 2)"), (V{4}));
    EXPECT_EQ(eval("ceil_div(8, 2)"), (V{4}));
    EXPECT_EQ(eval("ceil_div(-7, 2)"), (V{-3}));
    EXPECT_EQ(eval("ceil_div(0, 16)"), (V{0}));
}

TEST(SizeExpr, FunctionsAndVectors) {
    EXPECT_EQ(eval("view/2"), (V{320, 180}));
    EXPECT_EQ(eval("(view + 15) / 16"), (V{40, 23}));
    EXPECT_EQ(eval("ceil_div(view, 16)"), (V{40, 23}));
    EXPECT_EQ(eval("2 * view"), (V{1280, 720}));  // scalars broadcast on either side
    EXPECT_EQ(eval("view * view"), (V{409600, 129600}));
    EXPECT_EQ(eval("view - view"), (V{0, 0}));
    EXPECT_EQ(eval("view % 100"), (V{40, 60}));
    EXPECT_EQ(eval("-view"), (V{-640, -360}));
    EXPECT_EQ(eval("min(view, 400)"), (V{400, 360}));
    EXPECT_EQ(eval("max(view, 400)"), (V{640, 400}));
    EXPECT_EQ(eval("max(view.w, 1000) - min(3, 2) % 2"), (V{1000}));
    EXPECT_EQ(eval("min(max(1, 2), ceil_div(view.h, 7))"), (V{2}));
    EXPECT_EQ(eval("max( view.w , view.h )"), (V{640}));
}

TEST(SizeExpr, Extents) {
    SizeExpr lit;
    lit.literal = {256};
    auto e = eval_extent(lit, env(), 2);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->w, 256);  // size = 256 means 256x256
    EXPECT_EQ(e->h, 256);
    EXPECT_EQ(e->d, 1);
    auto c = eval_extent(lit, env(), 3);
    EXPECT_EQ(c->d, 256);  // and 256^3 for a 3D image
    auto v = eval_extent(text("view/2"), env(), 3);
    ASSERT_TRUE(v);
    EXPECT_EQ(v->w, 320);
    EXPECT_EQ(v->d, 1);    // a 2-vector in 3D has depth 1
    auto s = eval_extent(text("view.w / 10"), env(), 2);
    EXPECT_EQ(s->h, 64);   // expressions broadcast too
    lit.literal = {64, 32, 16};
    auto bad = eval_extent(lit, env(), 2);
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("not 3"), std::string::npos);
    EXPECT_EQ(eval_extent(lit, env(), 3)->d, 16);
    EXPECT_EQ(*eval_scalar(text("view.w * 4"), env()), 2560);
    auto vec = eval_scalar(text("view"), env());  // a vector where a number is needed
    ASSERT_FALSE(vec);
    EXPECT_NE(vec.error().message.find("2-vector"), std::string::npos);
    EXPECT_NE(vec.error().hint.find("view.w"), std::string::npos);
}

TEST(SizeExpr, DivisionByZeroPointsAtTheDivisor) {
    for (auto [t, offset] : {std::pair<const char*, size_t>{"view / 0", 7}, {"view.w % (1 - 1)", 9}, {"ceil_div(8, 0)", 12}}) {
        auto r = eval_size(text(t), env());
        ASSERT_FALSE(r) << t;
        EXPECT_NE(r.error().message.find("division by zero"), std::string::npos) << t;
        EXPECT_EQ(r.error().loc.line, 7);
        EXPECT_EQ(r.error().loc.col, col_of(offset)) << t;
    }
    EXPECT_FALSE(eval_size(text("view / (view - view)"), env()));  // any component
}

TEST(SizeExpr, UnknownNameSuggestsAndLists) {
    auto u = eval_size(text("veiw.w * 2"), env());
    ASSERT_FALSE(u);
    EXPECT_NE(u.error().message.find("unknown name 'veiw.w'"), std::string::npos);
    EXPECT_NE(u.error().message.find("\"veiw.w * 2\""), std::string::npos);  // the expression is quoted
    EXPECT_EQ(u.error().hint, "did you mean 'view.w'?");
    EXPECT_EQ(u.error().loc.file, "preset.toml");
    EXPECT_EQ(u.error().loc.line, 7);
    EXPECT_EQ(u.error().loc.col, col_of(0));
    ASSERT_FALSE(u.error().notes.empty());
    EXPECT_NE(u.error().notes[0].find("view.h"), std::string::npos);
    EXPECT_NE(u.error().notes[0].find("params.taps"), std::string::npos);

    auto p = eval_size(text("view.w / params.tap"), env());
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().hint, "did you mean 'params.taps'?");
    EXPECT_EQ(p.error().loc.col, col_of(9));
    auto bare = eval_size(text("taps * 2"), env());
    ASSERT_FALSE(bare);
    EXPECT_EQ(bare.error().loc.col, col_of(0));
}

TEST(SizeExpr, SyntaxErrorsPointAtTheToken) {
    struct Case {
        const char* text;
        size_t offset;
        const char* says;
    };
    for (const Case& c : {Case{"view.w $ 2", 7, "unexpected '$'"}, Case{"view.w * (2", 11, "expected ')'"},
                          Case{"view 2", 5, "expected an operator"}, Case{"view.w *", 8, "ends where a value"},
                          Case{"(view))", 6, "unbalanced ')'"}, Case{"2.5 * view", 0, "integers"},
                          Case{"min(view)", 8, "expected ','"}, Case{"max", 0, "two arguments"},
                          Case{"99999999999999999999", 0, "too large"}, Case{"view.w * 10000000000 * 10000000000", 21, "too large"}}) {
        auto r = eval_size(text(c.text), env());
        ASSERT_FALSE(r) << c.text;
        EXPECT_NE(r.error().message.find(c.says), std::string::npos) << c.text << ": " << r.error().message;
        EXPECT_EQ(r.error().loc.col, col_of(c.offset)) << c.text << ": " << r.error().message;
    }
    SizeExpr empty = text("   ");
    EXPECT_FALSE(eval_size(empty, env()));
}

TEST(SizeExpr, ComparisonsGiveOneOrZero) {
    EXPECT_EQ(eval("params.taps == 5"), (V{1}));
    EXPECT_EQ(eval("params.taps != 5"), (V{0}));
    EXPECT_EQ(eval("params.taps < 5"), (V{0}));
    EXPECT_EQ(eval("params.taps <= 5"), (V{1}));
    EXPECT_EQ(eval("params.taps > 4"), (V{1}));
    EXPECT_EQ(eval("params.taps >= 6"), (V{0}));
    EXPECT_EQ(eval("view.w / 2 == 320"), (V{1}));           // arithmetic binds tighter
    EXPECT_EQ(eval("(params.taps == 5) * 7 + 1"), (V{8}));  // a comparison in parentheses is a value
    EXPECT_EQ(eval("view == 640"), (V{1, 0}));              // per component, scalars broadcast
    EXPECT_EQ(eval("min(params.taps > 1, 1)"), (V{1}));
}

TEST(SizeExpr, EnumParamsCompareWithOptionNames) {
    EXPECT_EQ(eval("params.show == 'slices'"), (V{1}));
    EXPECT_EQ(eval("params.show == \"slices\""), (V{1}));  // either quote, for TOML's two string kinds
    EXPECT_EQ(eval("params.show == 'lit'"), (V{0}));
    EXPECT_EQ(eval("params.show != 'taa'"), (V{1}));
    EXPECT_EQ(eval("params.show >= 'count'"), (V{1}));  // option order
    EXPECT_EQ(eval("(params.show == 'lit') + (params.show == 'slices')"), (V{1}));

    auto typo = eval_size(text("params.show == 'slice'"), env());
    ASSERT_FALSE(typo);
    EXPECT_NE(typo.error().message.find("'slice' is not an option of params.show"), std::string::npos) << typo.error().message;
    EXPECT_EQ(typo.error().hint, "did you mean 'slices'?");
    EXPECT_EQ(typo.error().loc.col, col_of(16));  // inside the quotes

    auto not_enum = eval_size(text("params.taps == 'five'"), env());
    ASSERT_FALSE(not_enum);
    EXPECT_NE(not_enum.error().message.find("'params.taps' is not one"), std::string::npos) << not_enum.error().message;
    EXPECT_EQ(not_enum.error().loc.col, col_of(15));
}

TEST(SizeExpr, ComparisonErrorsPointAtTheToken) {
    struct Case {
        const char* text;
        size_t offset;
        const char* says;
    };
    for (const Case& c : {Case{"params.taps = 5", 12, "compare with =="}, Case{"1 < params.taps < 9", 16, "do not chain"},
                          Case{"'lit' == params.show", 0, "right of a comparison"}, Case{"params.show == 'lit", 15, "no closing"}}) {
        auto r = eval_size(text(c.text), env());
        ASSERT_FALSE(r) << c.text;
        EXPECT_NE(r.error().message.find(c.says), std::string::npos) << c.text << ": " << r.error().message;
        EXPECT_EQ(r.error().loc.col, col_of(c.offset)) << c.text << ": " << r.error().message;
    }
}

TEST(SizeExpr, NamesForMessages) {
    auto names = size_names(env());
    EXPECT_EQ(names[0], "view");
    EXPECT_NE(std::find(names.begin(), names.end(), "params.spread"), names.end());
    EXPECT_NE(std::find(names.begin(), names.end(), "ceil_div"), names.end());
}

TEST(SizeExpr, Log2FloorsAndCountsHalvings) {
    EXPECT_EQ(eval("log2(1)"), (V{0}));
    EXPECT_EQ(eval("log2(2)"), (V{1}));
    EXPECT_EQ(eval("log2(3)"), (V{1}));  // floor
    EXPECT_EQ(eval("log2(1024)"), (V{10}));
    EXPECT_EQ(eval("log2(1023)"), (V{9}));
    EXPECT_EQ(eval("log2(max(view.w, view.h))"), (V{9}));  // 640: levels 0..9, 9 halvings
    EXPECT_EQ(eval("log2(view)"), (V{9, 8}));              // per component
    EXPECT_EQ(eval("log2(max(view.w, view.h)) + 1"), (V{10}));
    auto zero = eval_size(text("log2(0)"), env());
    ASSERT_FALSE(zero);
    EXPECT_NE(zero.error().message.find("at least 1"), std::string::npos);
    EXPECT_EQ(zero.error().loc.col, col_of(5));  // at the argument
    auto two = eval_size(text("log2(4, 2)"), env());
    ASSERT_FALSE(two);
    EXPECT_NE(two.error().message.find("one argument"), std::string::npos);
}

TEST(SizeExpr, LocalsAreNamesOnlySomeExpressionsSee) {
    SizeEnv e = env();
    e.locals["iteration"] = 3;
    auto v = eval_size(text("iteration + 1"), e);
    ASSERT_TRUE(v);
    EXPECT_EQ(*v, (V{4}));
    auto none = eval_size(text("iteration + 1"), env());  // a size expression has no iteration
    ASSERT_FALSE(none);
    EXPECT_NE(none.error().message.find("unknown name 'iteration'"), std::string::npos);
    auto near = eval_size(text("iteraton"), e);
    ASSERT_FALSE(near);
    EXPECT_NE(near.error().hint.find("iteration"), std::string::npos);
}

// Float expressions (camera values): the same grammar over doubles.
namespace {
SizeEnv float_env() {
    SizeEnv e = env();
    e.vectors["dir"] = {0.0, 1.0, 2.0};
    return e;
}
std::vector<double> evalf(const std::string& t) {
    SizeEnv e = float_env();
    FloatExpr x;
    x.text = t;
    x.loc = {"preset.toml", 7, 10};
    auto r = eval_floats(x, e);
    EXPECT_TRUE(r) << t << ": " << (r ? "" : r.error().format());
    return r ? *r : std::vector<double>{};
}
Error float_error(const std::string& t) {
    FloatExpr x;
    x.text = t;
    x.loc = {"preset.toml", 7, 10};
    auto r = eval_floats(x, float_env());
    EXPECT_FALSE(r) << t;
    return r ? Error{} : r.error();
}
} // namespace

TEST(FloatExpr, RealArithmeticAndVectorParams) {
    using D = std::vector<double>;
    EXPECT_EQ(evalf("1.5 * 2"), (D{3.0}));
    EXPECT_EQ(evalf("7 / 2"), (D{3.5}));      // real division, not floor
    EXPECT_EQ(evalf(".5 + 1e-1"), (D{0.6}));
    EXPECT_EQ(evalf("params.spread"), (D{2.9}));  // not truncated
    EXPECT_EQ(evalf("params.dir * 10"), (D{0.0, 10.0, 20.0}));
    EXPECT_EQ(evalf("params.dir.z"), (D{2.0}));
    EXPECT_EQ(evalf("view / 2"), (D{320.0, 180.0}));
    EXPECT_NEAR(evalf("cos(radians(60))")[0], 0.5, 1e-12);
    EXPECT_NEAR(evalf("normalize(params.dir)")[2], 2.0 / std::sqrt(5.0), 1e-12);
    EXPECT_EQ(evalf("-7 % 2"), (D{1.0}));  // floors like the integer form
}

TEST(FloatExpr, ErrorsPointAtTheToken) {
    Error e = float_error("params.dri * 10");
    EXPECT_EQ(e.loc.col, col_of(0));
    EXPECT_NE(e.hint.find("params.dir"), std::string::npos) << e.format();
    e = float_error("1 / (2 - 2)");
    EXPECT_NE(e.message.find("division by zero"), std::string::npos);
    e = float_error("sqrt(-1)");
    EXPECT_NE(e.message.find("sqrt"), std::string::npos);
    e = float_error("2x");
    EXPECT_NE(e.message.find("not a number"), std::string::npos);
}
