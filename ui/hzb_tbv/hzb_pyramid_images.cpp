// The Z-pyramid images in the scene view's corner (ui/hzb_tbv/hzb_pyramid_images.h).
#include "ui/hzb_tbv/hzb_pyramid_images.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridcull {

namespace {

constexpr double kMargin = 12.0;     // view pixels from the view's edges
constexpr double kGap = 10.0;        // between images
constexpr double kLabelRows = 16.0;  // a label's height above its image
constexpr float kLabelScale = 1.5f;  // 10.5-pixel glyphs
constexpr float kFrameAlpha = 0.8f;
constexpr double kBackingPad = 6.0;
constexpr float kBackingAlpha = 0.75f;

const float* texelsOf(const HzbTbvSnapshot& s, const HzbPyramidLevel& l) {
    return s.pyramid_texels.data() + l.offset;
}

}  // namespace

int layoutHzbPyramidImages(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                           int view_width, int view_height, HzbPyramidImage* out) {
    if (!snapshot.valid || !view.show_pyramid || snapshot.pyramid_width <= 0 ||
        snapshot.pyramid_height <= 0)
        return 0;
    const int first = hzbFirstPyramidImage(snapshot, view);
    if (first < 0) return 0;
    const int count = std::min(kHzbPyramidImages, int(snapshot.pyramid_levels.size()) - first);
    const double room = (double(view_width) - 2.0 * kMargin - (count - 1) * kGap) / count;
    const double w = std::max(1.0, std::min(kHzbPyramidImageWidth, room));
    const double h = w * double(snapshot.pyramid_height) / double(snapshot.pyramid_width);
    const double y1 = double(view_height) - kMargin;
    for (int k = 0; k < count; ++k) {
        const double x0 = kMargin + k * (w + kGap);
        out[k] = {first + k, {x0, y1 - h, x0 + w, y1}};
    }
    return count;
}

HzbDepthRange hzbPyramidDepthRange(const HzbTbvSnapshot& snapshot, const HzbPyramidImage* images,
                                   int count) {
    HzbDepthRange range;
    for (int k = 0; k < count; ++k) {
        const HzbPyramidLevel& l = snapshot.pyramid_levels[size_t(images[k].index)];
        const float* texels = texelsOf(snapshot, l);
        const size_t n = size_t(l.width) * size_t(l.height);
        for (size_t i = 0; i < n; ++i) {
            if (!std::isfinite(texels[i])) continue;
            range.near = range.any ? std::min(range.near, double(texels[i])) : double(texels[i]);
            range.far = range.any ? std::max(range.far, double(texels[i])) : double(texels[i]);
            range.any = true;
        }
    }
    return range;
}

float hzbTexelGrey(float depth, const HzbDepthRange& range) {
    if (!std::isfinite(depth) || !range.any) return 0.0f;
    const double span = range.far - range.near;
    const double t = span > 0.0 ? std::clamp((double(depth) - range.near) / span, 0.0, 1.0) : 0.0;
    return float(1.0 - t * (1.0 - double(kHzbFarGrey)));
}

int drawHzbPyramidImages(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                         int view_width, int view_height, DebugDraw& draw) {
    HzbPyramidImage images[kHzbPyramidImages];
    const int count = layoutHzbPyramidImages(snapshot, view, view_width, view_height, images);
    if (count == 0) return 0;
    const HzbDepthRange range = hzbPyramidDepthRange(snapshot, images, count);
    const double w0 = double(snapshot.pyramid_width), h0 = double(snapshot.pyramid_height);
    // A dark backing under the images and their labels, so the labels read
    // over the scene.
    const ViewRect& last = images[count - 1].rect;
    draw.fillRect(DrawSpace::View, images[0].rect.x0 - kBackingPad,
                  images[0].rect.y0 - 2.0 * kLabelRows - kBackingPad, last.x1 + kBackingPad,
                  last.y1 + kBackingPad, {Swatch::NearBlack, kBackingAlpha});
    draw.text(DrawSpace::View, {images[0].rect.x0, images[0].rect.y0 - 2.0 * kLabelRows, 0.0},
              "Z-pyramid: near light, far dark, empty black", {Swatch::White}, kLabelScale);
    for (int k = 0; k < count; ++k) {
        const HzbPyramidImage& image = images[k];
        const HzbPyramidLevel& l = snapshot.pyramid_levels[size_t(image.index)];
        const ViewRect& r = image.rect;
        draw.fillRect(r, {Swatch::NearBlack});
        const float* texels = texelsOf(snapshot, l);
        // Texel (x, y) covers level-0 pixels [x 2^l, min((x+1) 2^l, w)) (z_pyramid.h).
        const double side = std::ldexp(1.0, l.level);
        const double sx = (r.x1 - r.x0) / w0, sy = (r.y1 - r.y0) / h0;
        for (int y = 0; y < l.height; ++y) {
            const double py0 = r.y0 + y * side * sy;
            const double py1 = r.y0 + std::min((y + 1) * side, h0) * sy;
            for (int x = 0; x < l.width; ++x) {
                const float grey =
                    hzbTexelGrey(texels[size_t(y) * size_t(l.width) + size_t(x)], range);
                if (grey <= 0.0f) continue;  // empty: the black backing shows
                draw.fillRect(DrawSpace::View, r.x0 + x * side * sx, py0,
                              r.x0 + std::min((x + 1) * side, w0) * sx, py1, {Swatch::White, grey});
            }
        }
        draw.outlineRect(r, {Swatch::LineGrey, kFrameAlpha}, kHairline);
        char label[64];
        std::snprintf(label, sizeof label, "level %d: %d x %d", l.level, l.width, l.height);
        draw.text(DrawSpace::View, {r.x0, r.y0 - kLabelRows, 0.0}, label, {Swatch::White},
                  kLabelScale);
    }
    return count;
}

}  // namespace gridcull
