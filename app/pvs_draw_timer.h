// The draw half of a frame's time: a PVS drawn with the project's OpenGL
// renderer (app/renderer.h) from the culling camera into an offscreen image of
// the oracle's size, as an application would draw what its culler kept, and
// timed from the first GL call to the end of glFinish (the GPU's work is
// finished before the clock stops). 3D scenes are drawn through the culling
// camera; 2D scenes as the top-down map of the world, the only picture a 2D
// scene has. Uses the process's hidden GL context (app/gl_context.h), so it
// needs an X display (xvfb-run on a headless machine; llvmpipe there).
//
// bench --draw gl times every algorithm's PVS, the `limit` (the exact visible
// set) and `all` with it; trade --draw gl every setting's.
#pragma once
#include <string>
#include <vector>

#include "app/offscreen_target.h"
#include "app/renderer.h"
#include "app/view_camera.h"
#include "culling/scene/scene.h"
#include "ui/object_state.h"

namespace gridcull {

class PvsDrawTimer {
public:
    // Makes the context, the target (`long_side` pixels on the long side, the
    // culling camera's aspect) and the renderer's buffers for `scene`.
    bool init(const Scene& scene, int long_side, std::string& error);
    // Draws the objects of `pvs` (ids, any order; ids not in the scene are
    // ignored) at time t and returns the milliseconds it took. Allocates nothing.
    double draw(const Scene& scene, const Camera& camera, double t, const std::vector<int>& pvs);
    // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)", for the report.
    std::string rendererName() const;
    int width() const { return target_.width(); }
    int height() const { return target_.height(); }
    // The last image drawn, RGBA rows from the top (for tests).
    void readPixels(std::vector<uint8_t>& rgba) const { target_.readPixelsTopDown(rgba); }

private:
    OffscreenTarget target_;
    Renderer renderer_;
    ViewCamera view_camera_;
    std::vector<ObjectState> states_;  // by object index
};

}  // namespace gridcull
