// Strict check parsing: every key and enumerated value of every check kind, each error at its
// value with a suggestion; buffer checks and counters.
#include "graph/parse.hpp"

#include <gtest/gtest.h>

using namespace pl;
using namespace pl::graph;

namespace {

// A test with one check `check` (an inline table body).
std::string with_check(const std::string& check) { return "[[test]]\nname = \"t\"\nchecks = [ { " + check + " } ]\n"; }

Error fails(const std::string& check) {
    auto g = parse_graph_text(with_check(check), "t/preset.toml");
    EXPECT_FALSE(g) << check;
    return g ? Error{} : g.error();
}

CheckDesc parses(const std::string& check) {
    auto g = parse_graph_text(with_check(check), "t/preset.toml");
    EXPECT_TRUE(g) << check << ": " << (g ? "" : g.error().format());
    return g && !g->tests.empty() && !g->tests[0].checks.empty() ? g->tests[0].checks[0] : CheckDesc{};
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

} // namespace

TEST(ParseChecks, UnknownKeysAndKindsSuggest) {
    Error e = fails("kind = \"matches_pass\", other = \"a\", tolerance = 0.1");
    EXPECT_TRUE(has(e.message, "unknown key 'tolerance'")) << e.message;
    EXPECT_EQ(e.hint, "did you mean 'tol'?");
    EXPECT_EQ(e.loc.line, 3);
    Error k = fails("kind = \"symetry\"");
    EXPECT_EQ(k.hint, "did you mean \"symmetry\"?");
    Error a = fails("kind = \"symmetry\", axis = \"z\"");
    EXPECT_TRUE(has(a.format(), "axis")) << a.format();
    Error typo = fails("kind = \"range\", mn = 0.0");
    EXPECT_EQ(typo.hint, "did you mean 'min'?");
    Error none = fails("other = \"a\"");
    EXPECT_TRUE(has(none.message, "needs kind"));
}

TEST(ParseChecks, ValuesAreRangeChecked) {
    EXPECT_TRUE(has(fails("kind = \"mean\", channels = [0, 5]").message, "channel 5"));
    EXPECT_TRUE(has(fails("kind = \"mean\", channel = 4").message, "channel"));
    EXPECT_TRUE(has(fails("kind = \"range\", fraction = 1.5").message, "[0, 1]"));
    EXPECT_TRUE(has(fails("kind = \"stable\", tol = -1").message, ">= 0"));
    EXPECT_TRUE(has(fails("kind = \"monotone\", param = \"p\", values = [1]").message, "at least 2"));
    EXPECT_TRUE(has(fails("kind = \"monotone\", param = \"p\", values = [1, 2], direction = \"up\"").format(), "direction"));
    EXPECT_TRUE(has(fails("kind = \"mean\", tol = \"x\"").message, "number"));
    EXPECT_TRUE(has(fails("kind = \"matches_pass\", other = \"a\", mask_channel = 1").message, "add mask"));
}

TEST(ParseChecks, ImageAndBufferKeysDoNotMix) {
    Error i = fails("kind = \"range\", index = 3");
    EXPECT_TRUE(has(i.hint, "add buffer")) << i.hint;
    Error p = fails("kind = \"range\", buffer = \"b\", px = [0, 0], min = 0");
    EXPECT_TRUE(has(p.message, "unknown key 'px'"));
    EXPECT_TRUE(has(fails("kind = \"symmetry\", buffer = \"b\"").message, "checks images"));
    EXPECT_TRUE(has(fails("kind = \"sorted\"").message, "add buffer"));
}

TEST(ParseChecks, BufferChecks) {
    CheckDesc c = parses("kind = \"probe\", buffer = \"b\", index = 0, type = \"uint\", expect = 0xffffffff");
    EXPECT_EQ(std::get<double>(c.args["expect"]), 4294967295.0);
    EXPECT_EQ(c.keys.at("buffer", {}).line, 3);
    parses("kind = \"sorted\", buffer = \"b\", stride = 8, field = 4, group = 16, order = \"descending\"");
    parses("kind = \"count\", buffer = \"b\", value = 1, expect = \"view.w*view.h\"");
    Error tol = fails("kind = \"probe\", buffer = \"b\", index = 0, type = \"int\", expect = -1, tol = 0.5");
    EXPECT_TRUE(has(tol.message, "compared exactly")) << tol.message;
    EXPECT_TRUE(has(fails("kind = \"sum\", buffer = \"b\", type = \"uint\", expect = 1, tol = 1").message, "compared exactly"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", index = 0, type = \"uint\", expect = -1").message, "not a 32-bit uint"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", index = 0, type = \"uint\", expect = 1.5").message, "not a 32-bit uint"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", expect = 1").message, "needs index"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", index = 0, range = [0, 2], expect = 1").message, "not both"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", range = [0, 3], expect = [1, 2]").message, "2 values for 3"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", index = 0, stride = 6, expect = 1").message, "multiple of 4"));
    EXPECT_TRUE(has(fails("kind = \"probe\", buffer = \"b\", index = 0, stride = 8, field = 8, expect = 1").message, "below stride"));
    EXPECT_TRUE(has(fails("kind = \"no_nan\", buffer = \"b\", type = \"int\"").message, "cannot be NaN"));
    EXPECT_TRUE(has(fails("kind = \"range\", buffer = \"b\"").message, "min and/or max"));
    EXPECT_TRUE(has(fails("kind = \"count\", buffer = \"b\", value = 1, min = 0, expect = 1").message, "not both"));
    EXPECT_TRUE(has(fails("kind = \"range\", buffer = \"b\", range = [0, 0], max = 1").message, "count >= 1"));
}

TEST(ParseChecks, ProbesKeepTheirShape) {
    auto g = parse_graph_text("[[test]]\nname = \"t\"\nprobes = [ { px = [0, 0], expect = [1], tol = 0, channel = 3 } ]\n", "t/preset.toml");
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_EQ(g->tests[0].checks[0].kind, "probe");
    EXPECT_FALSE(parse_graph_text("[[test]]\nname = \"t\"\nprobes = [ { px = [0, 0] } ]\n", "t/preset.toml"));
    EXPECT_FALSE(parse_graph_text("[[test]]\nname = \"t\"\nprobes = [ { uv = [0, 0], px = [0, 0], expect = [1] } ]\n", "t/preset.toml"));
    EXPECT_FALSE(parse_graph_text("[[test]]\nname = \"t\"\nprobes = [ { px = [0, 0], expect = [1, 2, 3, 4, 5] } ]\n", "t/preset.toml"));
}

TEST(ParseChecks, BufferCounter) {
    auto ok = parse_graph_text("[buffers]\nn = { size = 64, counter = { offset = 4, capacity = \"view.w\" } }\n", "t/preset.toml");
    ASSERT_TRUE(ok) << ok.error().format();
    ASSERT_TRUE(ok->buffers[0].counter);
    EXPECT_EQ(ok->buffers[0].counter->offset, 4u);
    EXPECT_EQ(ok->buffers[0].counter->capacity.text, "view.w");
    auto odd = parse_graph_text("[buffers]\nn = { size = 64, counter = { offset = 2, capacity = 4 } }\n", "t/preset.toml");
    ASSERT_FALSE(odd);
    EXPECT_TRUE(has(odd.error().message, "multiple of 4"));
    auto none = parse_graph_text("[buffers]\nn = { size = 64, counter = { offset = 0 } }\n", "t/preset.toml");
    ASSERT_FALSE(none);
    EXPECT_TRUE(has(none.error().message, "needs capacity"));
    auto typo = parse_graph_text("[buffers]\nn = { size = 64, counter = { offset = 0, capacity = 4, capactiy = 4 } }\n", "t/preset.toml");
    ASSERT_FALSE(typo);
    EXPECT_EQ(typo.error().hint, "did you mean 'capacity'?");
}

TEST(ParseChecks, ReductionNeedsAnImageAndAnOp) {
    CheckDesc c = parses("kind = \"reduction\", buffer = \"b\", index = 0, of = \"z\", op = \"min\", mask = \"m\", mask_channel = 3");
    EXPECT_EQ(c.kind, "reduction");
    EXPECT_TRUE(has(fails("kind = \"reduction\", buffer = \"b\", index = 0, op = \"min\"").message, "needs of = \"IMAGE\""));
    Error op = fails("kind = \"reduction\", buffer = \"b\", of = \"z\", op = \"mean\"");
    EXPECT_TRUE(has(op.format(), "op")) << op.format();
    EXPECT_TRUE(has(fails("kind = \"reduction\", of = \"z\", op = \"min\"").message, "checks a buffer"));
    EXPECT_TRUE(has(fails("kind = \"reduction\", buffer = \"b\", of = \"z\", op = \"min\", mask_channel = 1").message, "add mask"));
    EXPECT_TRUE(has(fails("kind = \"reduction\", buffer = \"b\", of = \"z\", op = \"min\", type = \"uint\", tol = 1").message, "compared exactly"));
}
