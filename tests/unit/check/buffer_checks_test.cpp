// Buffer checks on words built here: selection (index, range, stride, field), exact integer
// decoding (0xffffffff, negative ints), and each kind's verdict, including the failures.
#include "check/agreement.hpp"
#include "check/buffer_checks.hpp"
#include "check/properties.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace pl;
using namespace pl::check;

namespace {

uint32_t bits(float f) {
    uint32_t w;
    std::memcpy(&w, &f, 4);
    return w;
}

graph::CheckDesc make_check(const std::string& kind, Args args) {
    graph::CheckDesc c;
    c.kind = kind;
    c.args = std::move(args);
    return c;
}

CheckResult run(const std::vector<uint32_t>& words, const std::string& kind, Args args) {
    args["buffer"] = std::string("b");
    return buffer_property(words, make_check(kind, std::move(args)), graph::SizeEnv{});
}

} // namespace

TEST(BufferSelect, StrideAndFieldAddressWords) {
    // 4 elements of 8 bytes: { id, value }.
    std::vector<uint32_t> w = {0, 10, 1, 11, 2, 12, 3, 13};
    Args a{{"buffer", std::string("b")}, {"stride", 8.0}, {"field", 4.0}, {"type", std::string("uint")}};
    auto s = select(a, w.size());
    ASSERT_TRUE(s);
    EXPECT_EQ(s->count, 4u);
    EXPECT_EQ(decode(w, *s), (std::vector<double>{10, 11, 12, 13}));
    a["range"] = std::vector<double>{1, 2};
    s = select(a, w.size());
    ASSERT_TRUE(s);
    EXPECT_EQ(decode(w, *s), (std::vector<double>{11, 12}));
    a["range"] = std::vector<double>{3, 2};  // element 4 does not exist
    EXPECT_FALSE(select(a, w.size()));
}

TEST(BufferSelect, DecodesEveryTypeExactly) {
    std::vector<uint32_t> w = {0xffffffffu, 0x80000000u, bits(-0.25f)};
    Args a{{"buffer", std::string("b")}, {"type", std::string("uint")}};
    EXPECT_EQ(decode(w, *select(a, 3)), (std::vector<double>{4294967295.0, 2147483648.0, double(bits(-0.25f))}));
    a["type"] = std::string("int");
    EXPECT_EQ(decode(w, *select(a, 3))[0], -1.0);
    EXPECT_EQ(decode(w, *select(a, 3))[1], -2147483648.0);
    a["type"] = std::string("float");
    EXPECT_EQ(decode(w, *select(a, 3))[2], -0.25);
}

TEST(BufferChecks, IntegerProbeIsExact) {
    std::vector<uint32_t> w = {0xffffffffu, 7};
    EXPECT_TRUE(run(w, "probe", {{"index", 0.0}, {"type", std::string("uint")}, {"expect", 4294967295.0}}).passed);
    EXPECT_FALSE(run(w, "probe", {{"index", 0.0}, {"type", std::string("uint")}, {"expect", 4294967294.0}}).passed);
    EXPECT_TRUE(run(w, "probe", {{"index", 0.0}, {"type", std::string("int")}, {"expect", -1.0}}).passed);
    auto r = run(w, "probe", {{"range", std::vector<double>{0, 2}}, {"type", std::string("uint")}, {"expect", std::vector<double>{1, 7}}});
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.detail.find("element 0 = 4294967295 (0xffffffff), expected 1"), std::string::npos) << r.detail;
}

TEST(BufferChecks, FloatProbeComparesWithTheStoredFloat) {
    std::vector<uint32_t> w = {bits(0.1f)};
    EXPECT_TRUE(run(w, "probe", {{"index", 0.0}, {"expect", 0.1}}).passed);  // 0.1 rounds like the shader's
    EXPECT_FALSE(run(w, "probe", {{"index", 0.0}, {"expect", 0.1001}}).passed);
    EXPECT_TRUE(run(w, "probe", {{"index", 0.0}, {"expect", 0.1001}, {"tol", 1e-3}}).passed);
}

TEST(BufferChecks, ExpectExpressionUsesTheView) {
    std::vector<uint32_t> w = {640 * 360 * 3};
    graph::SizeEnv env;  // 640x360
    Args a{{"buffer", std::string("b")}, {"index", 0.0}, {"type", std::string("uint")}, {"expect", std::string("view.w*view.h*3")}};
    EXPECT_TRUE(buffer_property(w, make_check("probe", a), env).passed);
    env.view_w = 64;
    EXPECT_FALSE(buffer_property(w, make_check("probe", a), env).passed);
}

TEST(BufferChecks, SortedWithinGroups) {
    std::vector<uint32_t> w = {1, 2, 3, 0, 5, 9};  // groups of 3: [1,2,3] [0,5,9]
    EXPECT_TRUE(run(w, "sorted", {{"type", std::string("uint")}, {"group", 3.0}}).passed);
    auto whole = run(w, "sorted", {{"type", std::string("uint")}});
    EXPECT_FALSE(whole.passed);
    EXPECT_NE(whole.detail.find("element 2 = 3 > element 3 = 0"), std::string::npos) << whole.detail;
    EXPECT_FALSE(run(w, "sorted", {{"type", std::string("uint")}, {"group", 3.0}, {"order", std::string("descending")}}).passed);
    std::vector<uint32_t> nan = {bits(1.0f), 0x7fc00000u, bits(2.0f)};
    EXPECT_FALSE(run(nan, "sorted", {}).passed);  // NaN is never in order
}

TEST(BufferChecks, SumCountRangeNoNan) {
    std::vector<uint32_t> w = {0xffffffffu, 0xffffffffu, 3};
    auto u = std::string("uint");
    EXPECT_TRUE(run(w, "sum", {{"type", u}, {"expect", 2.0 * 4294967295.0 + 3}}).passed);  // no 32-bit wrap
    EXPECT_TRUE(run(w, "count", {{"type", u}, {"value", 4294967295.0}, {"expect", 2.0}}).passed);
    EXPECT_FALSE(run(w, "count", {{"type", u}, {"value", 4294967295.0}, {"expect", 3.0}}).passed);
    EXPECT_TRUE(run(w, "count", {{"type", u}, {"max", 10.0}, {"expect", 1.0}}).passed);
    EXPECT_FALSE(run(w, "range", {{"type", u}, {"max", 10.0}}).passed);
    EXPECT_TRUE(run(w, "range", {{"type", std::string("int")}, {"min", -1.0}, {"max", 3.0}}).passed);
    std::vector<uint32_t> f = {bits(1.0f), 0x7f800000u};
    EXPECT_FALSE(run(f, "no_nan", {}).passed);
    EXPECT_TRUE(run(f, "no_nan", {{"index", 0.0}}).passed);
}

TEST(Agreement, MaskAndFraction) {
    image::Image m;
    m.width = 4, m.height = 1;
    m.pixels = {1, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};  // pixels 0 and 2 in the mask
    std::vector<double> err = {0.0, 5.0, 0.5, 0.0};
    auto f = [&](size_t i, double& sq, size_t& n) {
        sq += err[i] * err[i];
        ++n;
        return err[i];
    };
    Agreement all = tally(4, Mask{}, 0.1, f);
    EXPECT_EQ(all.counted, 4u);
    EXPECT_EQ(all.passing, 2u);
    EXPECT_DOUBLE_EQ(all.worst, 5.0);
    Agreement in = tally(4, Mask{&m, 0, false}, 0.1, f);
    EXPECT_EQ(in.counted, 2u);
    EXPECT_EQ(in.passing, 1u);
    EXPECT_DOUBLE_EQ(in.rmse(), std::sqrt(0.25 / 2));
    Agreement out = tally(4, Mask{&m, 0, true}, 0.1, f);
    EXPECT_EQ(out.counted, 2u);
    EXPECT_EQ(out.passing, 1u);
}

// A mask that selects no pixel fails a range check and says so (not "values in [inf, -inf]").
TEST(Agreement, EmptyMaskFailsAndSaysNoPixelCounted) {
    image::Image img, none;
    img.width = none.width = 2, img.height = none.height = 1;
    img.pixels = {0.5f, 0.5f, 0.5f, 1, 0.5f, 0.5f, 0.5f, 1};
    none.pixels.assign(8, 0.0f);
    ImageLookup lookup = [&](const std::string&) -> Result<const image::Image*> { return &none; };
    auto r = image_property(img, make_check("range", {{"mask", std::string("none")}}), lookup);
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->passed);
    EXPECT_NE(r->detail.find("no pixel counted"), std::string::npos) << r->detail;
    EXPECT_EQ(r->detail.find("inf"), std::string::npos) << r->detail;
    auto all = image_property(img, make_check("range", {{"mask", std::string("none")}, {"invert_mask", true}}), lookup);
    ASSERT_TRUE(all);
    EXPECT_TRUE(all->passed) << all->detail;
    EXPECT_NE(all->detail.find("values in [0.5, 0.5]"), std::string::npos) << all->detail;
}

// `reduction`: the buffer's element against min/max/sum of an image channel reduced on the host,
// over the pixels a mask counts.
namespace {
image::Image tiny_image(const std::vector<float>& red, const std::vector<float>& alpha) {
    image::Image img;
    img.width = static_cast<int>(red.size());
    img.height = 1;
    img.pixels.assign(red.size() * 4, 0.0f);
    for (size_t i = 0; i < red.size(); ++i) img.pixels[i * 4] = red[i], img.pixels[i * 4 + 3] = alpha[i];
    return img;
}
CheckResult reduce(const std::vector<uint32_t>& w, Args a, const image::Image& of, const Mask& m = {}) {
    a["buffer"] = std::string("b");
    a["of"] = std::string("img");
    return buffer_reduction(w, make_check("reduction", std::move(a)), of, m);
}
} // namespace

TEST(BufferReduction, MinMaxExactOverTheMask) {
    // Pixel 1 (0.25) is masked out: the min over the mask is 0.5, not 0.25.
    image::Image img = tiny_image({0.75f, 0.25f, 0.5f, 3.0f}, {1, 0, 1, 1});
    Mask m{&img, 3, false};
    std::vector<uint32_t> w = {bits(0.5f), bits(3.0f)};
    EXPECT_TRUE(reduce(w, {{"op", std::string("min")}, {"index", 0.0}}, img, m).passed);
    EXPECT_TRUE(reduce(w, {{"op", std::string("max")}, {"index", 1.0}}, img, m).passed);
    CheckResult unmasked = reduce(w, {{"op", std::string("min")}, {"index", 0.0}}, img);
    EXPECT_FALSE(unmasked.passed);  // 0.25 without the mask
    EXPECT_NE(unmasked.detail.find("host min over 4 pixel(s) = 0.25"), std::string::npos) << unmasked.detail;
    // Exact: one ulp off fails without tol.
    std::vector<uint32_t> off = {bits(0.5f) + 1};
    EXPECT_FALSE(reduce(off, {{"op", std::string("min")}, {"index", 0.0}}, img, m).passed);
    EXPECT_TRUE(reduce(off, {{"op", std::string("min")}, {"index", 0.0}, {"tol", 1e-6}}, img, m).passed);
}

TEST(BufferReduction, SumIntegersAndEmptyMask) {
    image::Image img = tiny_image({1, 2, 3, 4}, {1, 1, 0, 1});
    Mask m{&img, 3, false};
    EXPECT_TRUE(reduce({7}, {{"op", std::string("sum")}, {"index", 0.0}, {"type", std::string("uint")}}, img, m).passed);
    EXPECT_FALSE(reduce({10}, {{"op", std::string("sum")}, {"index", 0.0}, {"type", std::string("uint")}}, img, m).passed);
    image::Image none = tiny_image({1, 2}, {0, 0});
    CheckResult r = reduce({0}, {{"op", std::string("max")}, {"index", 0.0}}, none, Mask{&none, 3, false});
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.detail.find("nothing to reduce"), std::string::npos) << r.detail;
    // Outside the buffer: the selection's error.
    EXPECT_FALSE(reduce({0}, {{"op", std::string("max")}, {"index", 3.0}}, img).passed);
}

TEST(BufferSorted, TolForgivesTinyStepsBack) {
    // 1 then 1 - 1.2e-7 (a weighted sum of ones): out of order exactly, in order within 1e-6.
    std::vector<uint32_t> w = {bits(0.5f), bits(1.0f), bits(0.99999988f), bits(1.0f)};
    EXPECT_FALSE(run(w, "sorted", {}).passed);
    EXPECT_TRUE(run(w, "sorted", {{"tol", 1e-6}}).passed);
    EXPECT_FALSE(run({bits(1.0f), bits(0.5f)}, "sorted", {{"tol", 1e-6}}).passed);
    EXPECT_TRUE(run({bits(1.0f), bits(0.99999988f)}, "sorted", {{"tol", 1e-6}, {"order", std::string("descending")}}).passed);
}
