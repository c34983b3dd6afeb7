#include "import/source_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using namespace pl::import;

namespace {
long lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n'); }
}

TEST(ImportSourceText, BomAndLineEndsGo) {
    EXPECT_EQ(clean_text("\xEF\xBB\xBFvoid f();\r\nint x;\rint y;\n"), "void f();\nint x;\nint y;\n");
}

TEST(ImportSourceText, EsToVulkanKeepsLines) {
    const std::string in = "#version 300 es\nprecision highp float;\nuniform float sampler; // sampler\nfloat buffer = 1.0;\n/* shared */ float shared2;\n";
    const std::string out = glsl_es_to_450(in);
    EXPECT_EQ(lines(out), lines(in));
    EXPECT_EQ(out.find("#version"), std::string::npos);
    EXPECT_NE(out.find("uniform float sampler_; // sampler"), std::string::npos) << out;  // comments untouched
    EXPECT_NE(out.find("float buffer_ = 1.0;"), std::string::npos);
    EXPECT_NE(out.find("/* shared */ float shared2;"), std::string::npos);  // not a whole word
}

TEST(ImportSourceText, ReplaceWordIsWholeWord) {
    EXPECT_EQ(replace_word("gl_FragColor = gl_FragColorX; // gl_FragColor", "gl_FragColor", "o"), "o = gl_FragColorX; // gl_FragColor");
    EXPECT_EQ(replace_word("x1e5 = 1e5;", "e5", "z"), "x1e5 = 1e5;");
}

TEST(ImportSourceText, LineColAndQuote) {
    EXPECT_EQ(line_col("ab\ncd", 4), std::make_pair(2, 2));
    EXPECT_EQ(toml_quote("a\"b\\c\nd"), "\"a\\\"b\\\\c\\nd\"");
}
