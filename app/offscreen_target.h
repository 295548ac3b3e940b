// A framebuffer object of a fixed size (RGBA8 colour, 24-bit depth) to render a
// shot into, whatever size the (hidden) window has. Needs a current GL context.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "app/gl_objects.h"

namespace gridcull {

class OffscreenTarget {
public:
    bool create(int width, int height, std::string& error);
    void bind() const;  // as the draw and read framebuffer
    // The colour buffer as RGBA rows from the top of the image down (PNG order).
    void readPixelsTopDown(std::vector<uint8_t>& rgba) const;
    int width() const { return width_; }
    int height() const { return height_; }

private:
    GlFramebuffer framebuffer_;
    GlRenderbuffer color_;
    GlRenderbuffer depth_;
    int width_ = 0, height_ = 0;
};

}  // namespace gridcull
