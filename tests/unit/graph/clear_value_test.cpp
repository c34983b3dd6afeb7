// Clear values per format class: integer formats take exact integers within their channel
// range, read through the union member Vulkan uses for the format.
#include "vk/clear_value.hpp"

#include <gtest/gtest.h>

#include <limits>

using namespace pl::vk;

namespace {
const FormatInfo& fmt(const char* name) {
    const FormatInfo* f = find_format(name);
    EXPECT_NE(f, nullptr) << name;
    return *f;
}
} // namespace

TEST(ClearValue, UnsignedTopValueIsExact) {
    VkClearColorValue v = clear_color(fmt("r32ui"), {4294967295.0, 0, 0, 0});
    EXPECT_EQ(v.uint32[0], 0xffffffffu);
    EXPECT_EQ(clear_value_problem(fmt("r32ui"), {4294967295.0, 0, 0, 0}), "");
}

TEST(ClearValue, SignedNegativeUsesInt32) {
    VkClearColorValue v = clear_color(fmt("r32i"), {-7, 0, 0, 0});
    EXPECT_EQ(v.int32[0], -7);
    EXPECT_EQ(clear_value_problem(fmt("r32i"), {-2147483648.0, 2147483647.0, 0, 0}), "");
    EXPECT_NE(clear_value_problem(fmt("r32i"), {2147483648.0, 0, 0, 0}), "");
}

TEST(ClearValue, FloatFormatsKeepFloatBits) {
    VkClearColorValue v = clear_color(fmt("rgba16f"), {5, 0.5, -1, 1});
    EXPECT_EQ(v.float32[0], 5.0f);
    EXPECT_EQ(v.float32[2], -1.0f);
    EXPECT_EQ(clear_value_problem(fmt("rgba8"), {2, -1, 0.5, 1}), "");  // clamped by the device, not an error
}

TEST(ClearValue, RangeFollowsChannelWidth) {
    EXPECT_EQ(clear_value_problem(fmt("rgba16ui"), {65535, 0, 1, 2}), "");
    std::string why = clear_value_problem(fmt("rgba16ui"), {0, 65536, 0, 0});
    EXPECT_NE(why.find("component 1"), std::string::npos) << why;
    EXPECT_NE(why.find("0..65535"), std::string::npos) << why;
}

TEST(ClearValue, IntegerFormatsRefuseFractionsNegativesAndNonFinite) {
    EXPECT_NE(clear_value_problem(fmt("r32ui"), {1.5, 0, 0, 0}), "");
    EXPECT_NE(clear_value_problem(fmt("r32ui"), {-1, 0, 0, 0}), "");
    EXPECT_NE(clear_value_problem(fmt("r32f"), {std::numeric_limits<double>::infinity(), 0, 0, 0}), "");
}

TEST(ClearValue, BufferFillIsOneUnsignedWord) {
    EXPECT_EQ(fill_value_problem(4294967295.0), "");
    EXPECT_EQ(fill_value_problem(0), "");
    EXPECT_NE(fill_value_problem(4294967296.0), "");
    EXPECT_NE(fill_value_problem(-1), "");
    EXPECT_NE(fill_value_problem(0.5), "");
}
