#include "mutate/mutants.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

using namespace pl::mutate;

namespace {
std::vector<std::string> applied(const std::string& src) {
    std::vector<std::string> out;
    for (const auto& m : find_mutants(src)) out.push_back(apply_mutant(src, m));
    return out;
}
bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }
} // namespace

TEST(Mutants, BinaryOperatorsAndComparisons) {
    auto v = applied("a = b + c * d; if (x < y) z = w >= 1;");
    EXPECT_TRUE(has(v, "a = b - c * d; if (x < y) z = w >= 1;"));
    EXPECT_TRUE(has(v, "a = b + c / d; if (x < y) z = w >= 1;"));
    EXPECT_TRUE(has(v, "a = b + c * d; if (x > y) z = w >= 1;"));
    EXPECT_TRUE(has(v, "a = b + c * d; if (x < y) z = w <= 1;"));
    EXPECT_TRUE(has(v, "a = b + c * d; if (x < y) z = w >= 2;"));  // integer nudged by one
}

TEST(Mutants, UnaryMinusIsDroppedNotSwapped) {
    auto v = applied("x = -y;");
    EXPECT_TRUE(has(v, "x = y;"));
    EXPECT_FALSE(has(v, "x = +y;"));
}

TEST(Mutants, CallsMinMaxNormalizeClamp) {
    auto v = applied("v = normalize(min(a, b)) + clamp(f(x, 1), 0.0, 1.0);");
    EXPECT_TRUE(has(v, "v = (min(a, b)) + clamp(f(x, 1), 0.0, 1.0);"));
    EXPECT_TRUE(has(v, "v = normalize(max(a, b)) + clamp(f(x, 1), 0.0, 1.0);"));
    EXPECT_TRUE(has(v, "v = normalize(min(a, b)) + (f(x, 1));"));
}

TEST(Mutants, FloatConstantsNudgedKeepingTheirType) {
    auto v = applied("x = 2.0 * y + 0.0 + 1e-3;");
    EXPECT_TRUE(has(v, "x = 2.2 * y + 0.0 + 1e-3;"));
    EXPECT_TRUE(has(v, "x = 2.0 * y + 0.1 + 1e-3;"));
    EXPECT_TRUE(has(v, "x = 2.0 * y + 0.0 + 0.0011;"));
}

TEST(Mutants, SwizzlesReversedOnlyWhenThatChangesThem) {
    auto v = applied("a = b.xy + c.rgb + d.xx + s.position;");
    EXPECT_TRUE(has(v, "a = b.yx + c.rgb + d.xx + s.position;"));
    EXPECT_TRUE(has(v, "a = b.xy + c.bgr + d.xx + s.position;"));
    for (const auto& m : find_mutants("a = b.xy + c.rgb + d.xx + s.position;")) {
        if (m.op == "reverse swizzle") {
            EXPECT_NE(m.replacement, "xx");
        }
    }
}

TEST(Mutants, CommentsDirectivesLayoutsAndArraySizesAreLeftAlone) {
    const std::string src =
        "#version 450\n#define K (a + b)\n// x = y + z;\n/* p < q */\n"
        "layout(location = 1, local_size_x = 8) in vec2 uv;\nfloat arr[4];\n";
    auto ms = find_mutants(src);
    for (const auto& m : ms) {
        ADD_FAILURE() << "unexpected mutant " << m.op << " at " << m.line << ":" << m.col;
    }
}

TEST(Mutants, PositionsAndLines) {
    const std::string src = "void f() {\n    y = a + b;\n}\n";
    auto ms = find_mutants(src);
    ASSERT_EQ(ms.size(), 1u);
    EXPECT_EQ(ms[0].line, 2);
    EXPECT_EQ(ms[0].col, 11);
    EXPECT_EQ(line_of(src, ms[0]), "    y = a + b;");
    EXPECT_EQ(mutated_line_of(src, ms[0]), "    y = a - b;");
}

TEST(Mutants, LongLinesAreLinear) {
    // 200,000 characters of whitespace and one expression: the scanner must not recurse.
    std::string src(200000, ' ');
    src += "y = a + b;";
    EXPECT_EQ(find_mutants(src).size(), 1u);
}

TEST(Choose, DeterministicPermutationPrefix) {
    auto a = choose(100, 10, 7), b = choose(100, 10, 7), c = choose(100, 10, 8);
    EXPECT_EQ(a, b);
    EXPECT_NE(a, c);
    std::set<size_t> uniq(a.begin(), a.end());
    EXPECT_EQ(uniq.size(), 10u);
    for (size_t i : a) EXPECT_LT(i, 100u);
    EXPECT_EQ(choose(5, 10, 1).size(), 5u);
    // Pinned: the same choice on every machine and standard library.
}
