#include "import/isf.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace pl::import;

TEST(ImportIsf, SizeExpressions) {
    EXPECT_EQ(*isf_size_expression("$WIDTH/2", {}), "view.w/2");
    EXPECT_EQ(*isf_size_expression("floor($HEIGHT/4)", {}), "(view.h/4)");
    EXPECT_EQ(*isf_size_expression("max(1, $WIDTH/$scale)", {}), "max(1, view.w/params.scale)");
    EXPECT_EQ(*isf_size_expression("2.0*$WIDTH", {}), "2*view.w");
    EXPECT_EQ(*isf_size_expression("$cells", {}, {{"cells", "(X)"}}), "(X)");
    EXPECT_FALSE(isf_size_expression("$WIDTH*0.5", {}).ok());
    EXPECT_FALSE(isf_size_expression("ceil($WIDTH/3)", {}).ok());
}

TEST(ImportIsf, HeaderAndRewrites) {
    const std::string src = "/*{ \"INPUTS\": [ { \"NAME\": \"gain\", \"TYPE\": \"float\", \"DEFAULT\": 0.5, \"MIN\": 0, \"MAX\": 2 },\n"
                            "  { \"NAME\": \"mode\", \"TYPE\": \"long\", \"VALUES\": [3, 5], \"LABELS\": [\"Three\", \"Five\"] } ],\n"
                            "  \"PASSES\": [ { \"TARGET\": \"acc\", \"PERSISTENT\": true, \"FLOAT\": true }, {} ] }*/\n"
                            "varying vec2 v;\nvoid main() { gl_FragColor = texture2D(acc, v) * gain; }\n";
    auto d = read_isf(src, "x.fs");
    ASSERT_TRUE(d.ok()) << d.error().format();
    ASSERT_EQ(d->inputs.size(), 2u);
    EXPECT_EQ(d->inputs[0].max, std::vector<double>{2.0});
    EXPECT_EQ(d->inputs[1].values, (std::vector<int>{3, 5}));
    ASSERT_EQ(d->passes.size(), 2u);
    EXPECT_TRUE(d->passes[0].persistent && d->passes[0].is_float);
    EXPECT_NE(d->code.find("in vec2 v;"), std::string::npos);
    EXPECT_NE(d->code.find("isf_FragColor = texture(acc, v) * gain;"), std::string::npos) << d->code;
    EXPECT_EQ(std::count(d->code.begin(), d->code.end(), '\n'), std::count(src.begin(), src.end(), '\n'));
}

TEST(ImportIsf, BadJsonIsLocated) {
    auto d = read_isf("// c\n/*{\n \"INPUTS\": [ } ]\n}*/\nvoid main() {}\n", "x.fs");
    ASSERT_FALSE(d.ok());
    EXPECT_EQ(d.error().loc.line, 3);
    EXPECT_NE(d.error().message.find("not valid JSON"), std::string::npos);
}
