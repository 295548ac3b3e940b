// The Z-pyramid (Greene et al.; Sudarsky & Gotsman section 2.1.1 and 4) as small
// grey-scale images in the bottom-left corner of the scene view, in View space:
// kHzbPyramidImages consecutive levels from the one hzbFirstPyramidImage picks,
// finer to coarser left to right, each labelled with its level and size. A
// texel is a rectangle over its footprint of level-0 pixels, so every image has
// the z-buffer's aspect and coarse levels show as coarse blocks of the same
// picture. Grey: near = light, far = dark over one depth range shared by the
// images shown, empty (+infinity: nothing drawn under the footprint) = black.
//
// Cost per draw: O(texels of the levels shown) rectangles (at most
// kHzbMaxCapturedSide^2 a level, 64^2 with the default pick); allocates nothing.
#pragma once
#include "culling/hzb_tbv/hzb_tbv_snapshot.h"
#include "ui/debug_draw.h"
#include "ui/hzb_tbv/hzb_tbv_view.h"

namespace gridcull {

// One image's place in the view.
struct HzbPyramidImage {
    int index = -1;  // into snapshot.pyramid_levels
    ViewRect rect;   // the image (texels), its label above it
};

// The images' width in view pixels, less when the view is too narrow for them.
constexpr double kHzbPyramidImageWidth = 200.0;

// Lays out the images for a view_width x view_height view; writes up to
// kHzbPyramidImages to `out` and returns how many.
int layoutHzbPyramidImages(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                           int view_width, int view_height, HzbPyramidImage* out);

// The depth range the grey ramp spans: the nearest and farthest finite texels
// of the levels shown; `any` false when every texel is empty.
struct HzbDepthRange {
    double near = 0.0, far = 0.0;
    bool any = false;
};
HzbDepthRange hzbPyramidDepthRange(const HzbTbvSnapshot& snapshot, const HzbPyramidImage* images,
                                   int count);
// A texel's grey, the opacity of white over the black image: 0 for an empty
// texel, kHzbFarGrey (farthest) to 1 (nearest) for a drawn one.
constexpr float kHzbFarGrey = 0.2f;
float hzbTexelGrey(float depth, const HzbDepthRange& range);

// Draws the images (nothing when the snapshot is not valid, the pyramid is not
// shown, or nothing was captured); returns how many.
int drawHzbPyramidImages(const HzbTbvSnapshot& snapshot, const HzbTbvViewState& view,
                         int view_width, int view_height, DebugDraw& draw);

}  // namespace gridcull
