// Where the image viewer puts the image in the view: fitted (scaled to fit, centred) until the
// user zooms or pans, then a free transform. Zoom snaps to whole powers of two at and above 1:1
// so magnified texels are squares of whole pixels, and it keeps the texel under the cursor
// where it is. vkCmdBlitImage takes integer texel rectangles inside both images, so a texel the
// border cuts is drawn by a blit of its own (blit_regions).
#pragma once

#include <array>
#include <vector>

namespace pl::lab {

// Screen position of texel corner (u, v): (x + u * scale, y + v * scale), in view pixels.
struct FitRect {
    float x = 0, y = 0, scale = 1;
};
// An image of w x h scaled to fit a view of W x H, centred, aspect kept.
FitRect fit_rect(int w, int h, int W, int H);

struct ViewerView {
    bool fitted = true;  // follows fit_rect (a resize or another image keeps it fitting)
    FitRect free;        // the transform once zoomed or panned
};

// The transform in use for an image of w x h in a view of W x H.
FitRect view_rect(const ViewerView& v, int w, int h, int W, int H);
// Zooms by 2^steps about view point (px, py), starting from `current` (view_rect's result).
void zoom_at(ViewerView& v, const FitRect& current, double steps, float px, float py);
// Moves the image by (dx, dy) view pixels.
void pan_by(ViewerView& v, const FitRect& current, float dx, float dy);

// Blits that draw a w x h image under r into a W x H view: source texels [sx0, sx1) x [sy0, sy1)
// to view pixels [dx0, dx1) x [dy0, dy1). The texels wholly inside go in one blit at exactly r's
// scale; a texel cut by the view's border gets its own blit into what is left of it (one texel
// squeezed is still its colour, where squeezing it with its neighbours would shift them all).
struct BlitRegion {
    int sx0 = 0, sy0 = 0, sx1 = 0, sy1 = 0;
    int dx0 = 0, dy0 = 0, dx1 = 0, dy1 = 0;
};
std::vector<BlitRegion> blit_regions(const FitRect& r, int w, int h, int W, int H);

// The texel under view point (px, py) (may lie outside the image: callers bound it).
std::array<int, 2> texel_at(const FitRect& r, float px, float py);

} // namespace pl::lab
