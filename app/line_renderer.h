// Draws coloured lines and translucent triangles (ColorVertex lists) with one
// small shader: the overlays of the scene view. Needs a current GL 3.3 context.
#pragma once
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>

#include "app/gl_objects.h"
#include "app/overlay_geometry.h"

namespace gridcull {

class LineRenderer {
public:
    bool init(std::string& error);
    // mode: GL_LINES or GL_TRIANGLES. width: line width in pixels, clamped to what
    // the driver allows. Blends by alpha; depth test on or off as asked, never
    // writes depth. Uploads into a reused buffer.
    void draw(const std::vector<ColorVertex>& vertices, GLenum mode,
              const glm::mat4& view_projection, float width, bool depth_test);

private:
    GlProgram program_;
    GLint view_projection_location_ = -1;
    GlVertexArray vao_;
    StreamBuffer vertices_;
    float max_width_ = 1.0f;
};

}  // namespace gridcull
