// The pixel view the oracle's geometry tests share: the eye at the origin
// looking down +z (x right, y up), fov 90 each way, near 0.1, far 1000, an
// image of side x side pixels. Pixel column px then spans slopes
// u in [2 px / side - 1, 2 (px + 1) / side - 1], row py slopes v from
// 1 - 2 py / side down to 1 - 2 (py + 1) / side.
#pragma once
#include "culling/oracle/pixel_pyramid.h"

namespace gridcull::test {

inline PixelView squarePixelView(int side) {
    PixelView view;
    view.eye = {0, 0, 0};
    view.right = {1, 0, 0};
    view.up = {0, 1, 0};
    view.forward = {0, 0, 1};
    view.tan_x = view.tan_y = 1.0;
    view.near = 0.1;
    view.far = 1000.0;
    view.width = view.height = side;
    return view;
}

}  // namespace gridcull::test
