// The OpenGL side of the debug-draw interface (ui/debug_draw.h): draws what a
// family's overlay emitted into a DebugDrawBatch, in the batch's fixed order
// (per space: fills, lines thinnest first, text), World space through the
// view's camera and View space as pixels of the current viewport. Text labels
// are stb_easy_font's segment glyphs as quads, with a one-pixel shadow so they
// read over any background. Buffers are reused: a steady state allocates
// nothing. Needs a current GL 3.3 core context.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "app/line_renderer.h"
#include "ui/debug_draw.h"

namespace gridcull {

class GlDebugDraw {
public:
    bool init(std::string& error) { return lines_.init(error); }
    // Where overlays emit; clear it before a frame's overlay.
    DebugDrawBatch& batch() { return batch_; }
    // Draws the batch into the current viewport, view_width x view_height pixels.
    void flush(const glm::mat4& view_projection, int view_width, int view_height);

private:
    void appendLabel(const DebugDrawBatch::Label& label, const glm::vec2& at);

    LineRenderer lines_;
    DebugDrawBatch batch_;
    std::vector<ColorVertex> text_;  // label triangles, view pixels
    std::vector<char> glyphs_;       // stb_easy_font's quads for one label
    std::string label_;              // one label's text, printable ASCII only
};

}  // namespace gridcull
