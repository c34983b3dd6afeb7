// The image viewer's zoom and pan: the texel under the cursor stays there, magnified texels are
// whole pixels, and the blit never leaves the view (Vulkan requires it) nor shifts a texel.
#include "viewer_view.hpp"

#include <gtest/gtest.h>

using namespace pl::lab;

TEST(ViewerView, FitCentresAndKeepsAspect) {
    FitRect r = fit_rect(100, 50, 400, 400);
    EXPECT_FLOAT_EQ(r.scale, 4.0f);
    EXPECT_FLOAT_EQ(r.x, 0.0f);
    EXPECT_FLOAT_EQ(r.y, 100.0f);
}

TEST(ViewerView, ZoomKeepsTheTexelUnderTheCursor) {
    ViewerView v;
    const FitRect fit = view_rect(v, 64, 64, 640, 360);  // scale 5.625, x 140
    const float px = 333.3f, py = 171.9f;
    const auto before = texel_at(fit, px, py);
    zoom_at(v, fit, 2.0, px, py);
    ASSERT_FALSE(v.fitted);
    const FitRect r = view_rect(v, 64, 64, 640, 360);
    EXPECT_FLOAT_EQ(r.scale, 16.0f);  // 5.625 * 4 = 22.5 snaps to the nearest power of two (log2 4.49)
    EXPECT_EQ(texel_at(r, px, py), before);
    // Zooming back out below 1:1 is free (no snapping), and the point still holds.
    ViewerView w;
    zoom_at(w, fit_rect(4096, 4096, 640, 360), -1.0, 10.0f, 10.0f);
    EXPECT_NEAR(view_rect(w, 4096, 4096, 640, 360).scale, 360.0f / 4096.0f / 2.0f, 1e-6);
}

TEST(ViewerView, ZoomIsBounded) {
    ViewerView v;
    FitRect r = fit_rect(8, 8, 640, 360);
    for (int i = 0; i < 40; ++i) zoom_at(v, r = view_rect(v, 8, 8, 640, 360), 1.0, 320, 180);
    EXPECT_FLOAT_EQ(view_rect(v, 8, 8, 640, 360).scale, 256.0f);
}

TEST(ViewerView, PanMovesByViewPixels) {
    ViewerView v;
    const FitRect fit = view_rect(v, 64, 32, 640, 320);  // scale 10, x 0, y 0
    pan_by(v, fit, 25.0f, -7.0f);
    const FitRect r = view_rect(v, 64, 32, 640, 320);
    EXPECT_FLOAT_EQ(r.x, 25.0f);
    EXPECT_FLOAT_EQ(r.y, -7.0f);
    EXPECT_EQ(texel_at(r, 25.0f + 10.0f * 3 + 0.5f, -7.0f + 10.0f * 2 + 0.5f), (std::array<int, 2>{3, 2}));
}

namespace {
// Every view pixel the image covers is written exactly once, by a blit whose scale is r's or
// which holds one texel (squeezing one texel shifts nothing).
void expect_exact_cover(const FitRect& r, int w, int h, int W, int H) {
    std::vector<int> hits(static_cast<size_t>(W) * H, 0);
    for (const BlitRegion& b : blit_regions(r, w, h, W, H)) {
        ASSERT_GE(b.dx0, 0);
        ASSERT_LE(b.dx1, W);
        ASSERT_GE(b.dy0, 0);
        ASSERT_LE(b.dy1, H);
        ASSERT_GE(b.sx0, 0);
        ASSERT_LE(b.sx1, w);
        ASSERT_LT(b.dx0, b.dx1);
        ASSERT_LT(b.dy0, b.dy1);
        if (b.sx1 - b.sx0 > 1) {
            EXPECT_NEAR(static_cast<double>(b.dx1 - b.dx0) / (b.sx1 - b.sx0), r.scale, 1.0 / (b.sx1 - b.sx0));
        }
        if (b.sy1 - b.sy0 > 1) {
            EXPECT_NEAR(static_cast<double>(b.dy1 - b.dy0) / (b.sy1 - b.sy0), r.scale, 1.0 / (b.sy1 - b.sy0));
        }
        for (int y = b.dy0; y < b.dy1; ++y)
            for (int x = b.dx0; x < b.dx1; ++x) ++hits[static_cast<size_t>(y) * W + x];
    }
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            // The image's footprint (pixel centres inside it) is covered once, the rest never.
            const float u = (x + 0.5f - r.x) / r.scale, v = (y + 0.5f - r.y) / r.scale;
            const bool inside = u >= 0 && v >= 0 && u < w && v < h;
            ASSERT_EQ(hits[static_cast<size_t>(y) * W + x], inside ? 1 : 0) << "pixel " << x << ", " << y;
        }
}
} // namespace

TEST(ViewerView, CutTexelsAtTheBorderGetTheirOwnBlit) {
    // Scale 8, origin (-13, 5): texel 1 is cut at the left (pixels 0..2), texels 2..25 are whole
    // (3..195), texel 26 is cut at the right (195..199); rows 0..5 whole, row 6 cut at 60.
    const FitRect r{-13.0f, 5.0f, 8.0f};
    const auto b = blit_regions(r, 100, 10, 200, 60);
    ASSERT_EQ(b.size(), 6u);  // 3 columns x 2 rows of segments
    EXPECT_EQ((std::array<int, 4>{b[0].sx0, b[0].sx1, b[0].dx0, b[0].dx1}), (std::array<int, 4>{1, 2, 0, 3}));
    EXPECT_EQ((std::array<int, 4>{b[1].sx0, b[1].sx1, b[1].dx0, b[1].dx1}), (std::array<int, 4>{2, 26, 3, 195}));
    EXPECT_EQ((std::array<int, 4>{b[2].sx0, b[2].sx1, b[2].dx0, b[2].dx1}), (std::array<int, 4>{26, 27, 195, 200}));
    EXPECT_EQ((std::array<int, 4>{b[0].sy0, b[0].sy1, b[0].dy0, b[0].dy1}), (std::array<int, 4>{0, 6, 5, 53}));
    EXPECT_EQ((std::array<int, 4>{b[3].sy0, b[3].sy1, b[3].dy0, b[3].dy1}), (std::array<int, 4>{6, 7, 53, 60}));
    expect_exact_cover(r, 100, 10, 200, 60);
}

TEST(ViewerView, EveryZoomAndPanCoversTheViewExactly) {
    expect_exact_cover(fit_rect(640, 360, 640, 360), 640, 360, 640, 360);
    expect_exact_cover(fit_rect(8, 8, 320, 200), 8, 8, 320, 200);
    expect_exact_cover(FitRect{-158.4f, -156.0f, 64.0f}, 8, 8, 320, 200);  // the live test's zoom
    expect_exact_cover(FitRect{-1000.0f, -1000.0f, 256.0f}, 16, 16, 200, 100);  // one texel fills the view
    expect_exact_cover(FitRect{3.3f, 7.7f, 0.25f}, 400, 300, 120, 90);  // zoomed out
    // Panned away entirely: nothing to blit.
    EXPECT_TRUE(blit_regions(FitRect{700.0f, 0.0f, 2.0f}, 100, 10, 200, 60).empty());
    EXPECT_TRUE(blit_regions(FitRect{-500.0f, 0.0f, 2.0f}, 100, 10, 200, 60).empty());
}
