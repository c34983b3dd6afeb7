// The viewer's statistics and auto-exposure, on images whose answers are known.
#include "image_stats.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pl;
using namespace pl::lab;

namespace {
image::Image ramp(int n, float scale) {  // texel i of n holds (i, 2i, -i, 1) * scale
    image::Image img;
    img.width = n, img.height = 1;
    for (int i = 0; i < n; ++i) img.pixels.insert(img.pixels.end(), {i * scale, 2 * i * scale, -i * scale, 1.0f});
    return img;
}
} // namespace

TEST(ImageStats, MinMaxMeanPerChannel) {
    const ImageStats s = image_stats(ramp(101, 0.01f), 1);
    EXPECT_FLOAT_EQ(s.min[0], 0.0f);
    EXPECT_FLOAT_EQ(s.max[0], 1.0f);
    EXPECT_NEAR(s.mean[0], 0.5f, 1e-6);
    EXPECT_FLOAT_EQ(s.max[1], 2.0f);
    EXPECT_FLOAT_EQ(s.min[2], -1.0f);
    EXPECT_FLOAT_EQ(s.mean[3], 1.0f);
    EXPECT_EQ(s.texels, 101u);
    EXPECT_EQ(s.nonfinite, 0u);
}

TEST(ImageStats, HistogramCountsEveryFiniteTexelOfTheShownChannel) {
    const ImageStats s = image_stats(ramp(100, 1.0f), 2, 10);  // G: 0, 2, ..., 198
    ASSERT_EQ(s.histogram.size(), 10u);
    EXPECT_FLOAT_EQ(s.lo, 0.0f);
    EXPECT_FLOAT_EQ(s.hi, 198.0f);
    float total = 0;
    for (float c : s.histogram) {
        total += c;
        EXPECT_FLOAT_EQ(c, 10.0f);
    }
    EXPECT_FLOAT_EQ(total, 100.0f);
}

TEST(ImageStats, NonFiniteTexelsAreCountedAndLeftOut) {
    image::Image img = ramp(10, 1.0f);
    img.pixels[4 * 3 + 1] = NAN;
    img.pixels[4 * 7 + 0] = INFINITY;
    const ImageStats s = image_stats(img, 1);
    EXPECT_EQ(s.nonfinite, 2u);
    EXPECT_FLOAT_EQ(s.max[0], 9.0f);
    EXPECT_NEAR(s.mean[0], (45.0f - 3.0f - 7.0f) / 8.0f, 1e-6);
}

TEST(ImageStats, AutoExposureMapsThe99thPercentileToWhite) {
    // 1000 texels of luminance i/1000 * 8 in R=G=B, and one hot outlier of 1e6.
    image::Image img;
    img.width = 1001, img.height = 1;
    for (int i = 1; i <= 1000; ++i) img.pixels.insert(img.pixels.end(), {i * 0.008f, i * 0.008f, i * 0.008f, 1.0f});
    img.pixels.insert(img.pixels.end(), {1e6f, 1e6f, 1e6f, 1.0f});
    const ImageStats s = image_stats(img, 0);
    // Nearest rank: ceil(0.99 * 1001) = 991st smallest = 991 * 0.008.
    EXPECT_NEAR(s.p99, 991 * 0.008f, 1e-3);
    EXPECT_NEAR(auto_exposure_ev(s), -std::log2(991 * 0.008f), 1e-4);  // the outlier does not count
    EXPECT_FLOAT_EQ(auto_exposure_ev(image_stats(ramp(5, 0.0f), 0)), 0.0f);  // black: no exposure
}

TEST(ImageStats, HdrRangesAreBinnedInLog2) {
    // 1, 2, 4, ..., 2^9 in R: ten stops, one value per bin of a 10-bin log2 histogram.
    image::Image img;
    img.width = 10, img.height = 1;
    for (int i = 0; i < 10; ++i) img.pixels.insert(img.pixels.end(), {std::exp2(static_cast<float>(i)), 0.0f, 0.0f, 1.0f});
    const ImageStats s = image_stats(img, 1, 10);
    EXPECT_TRUE(s.log_scale);
    for (float c : s.histogram) EXPECT_FLOAT_EQ(c, 1.0f);
    EXPECT_FALSE(image_stats(ramp(100, 1.0f), 2, 10).log_scale);  // starts at 0: linear
}
