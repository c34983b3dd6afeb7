#include "graph/sizeexpr.hpp"

#include <gtest/gtest.h>

using namespace pl;
using namespace pl::graph;

namespace {
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
    return e;
}
} // namespace

TEST(SizeExpr, ViewAndVectorArithmetic) {
    EXPECT_EQ(*eval_size(text("view"), env()), (std::vector<int64_t>{640, 360}));
    EXPECT_EQ(*eval_size(text("view/2"), env()), (std::vector<int64_t>{320, 180}));
    EXPECT_EQ(*eval_size(text("view.w*view.h*4"), env()), (std::vector<int64_t>{921600}));
    EXPECT_EQ(*eval_size(text("(view + 15) / 16"), env()), (std::vector<int64_t>{40, 23}));
    EXPECT_EQ(*eval_size(text("ceil_div(view, 16)"), env()), (std::vector<int64_t>{40, 23}));
    EXPECT_EQ(*eval_size(text("max(view.w, 1000) - min(3, 2) % 2"), env()), (std::vector<int64_t>{1000}));
    EXPECT_EQ(*eval_size(text("params.taps * 2 + -1"), env()), (std::vector<int64_t>{9}));
    EXPECT_EQ(*eval_size(text("2 + 3 * 4"), env()), (std::vector<int64_t>{14}));  // precedence
}

TEST(SizeExpr, LiteralsAndExtents) {
    SizeExpr lit;
    lit.literal = {256};
    auto e = eval_extent(lit, env(), 2);
    ASSERT_TRUE(e);
    EXPECT_EQ(e->w, 256);
    EXPECT_EQ(e->h, 256);
    auto c = eval_extent(lit, env(), 3);
    EXPECT_EQ(c->d, 256);
    lit.literal = {64, 32, 16};
    EXPECT_FALSE(eval_extent(lit, env(), 2));
    EXPECT_EQ(eval_extent(lit, env(), 3)->d, 16);
    EXPECT_FALSE(eval_scalar(text("view"), env()));  // a vector where a number is needed
}

TEST(SizeExpr, ErrorsPointAtTheToken) {
    auto d = eval_size(text("view / 0"), env());
    ASSERT_FALSE(d);
    EXPECT_NE(d.error().message.find("division by zero"), std::string::npos);
    auto u = eval_size(text("veiw.w * 2"), env());
    ASSERT_FALSE(u);
    EXPECT_NE(u.error().message.find("unknown name 'veiw.w'"), std::string::npos);
    EXPECT_EQ(u.error().hint, "did you mean 'view.w'?");
    EXPECT_EQ(u.error().loc.line, 7);
    EXPECT_EQ(u.error().loc.col, 11);  // opening quote at 10, token at offset 0
    auto p = eval_size(text("view.w * (2"), env());
    ASSERT_FALSE(p);
    EXPECT_NE(p.error().message.find("expected ')'"), std::string::npos);
    auto j = eval_size(text("view.w $ 2"), env());
    ASSERT_FALSE(j);
    EXPECT_EQ(j.error().loc.col, 10 + 1 + 7);
}
