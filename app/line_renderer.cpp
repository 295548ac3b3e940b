#include "app/line_renderer.h"

#include <algorithm>
#include <cstddef>

#include <glm/gtc/type_ptr.hpp>

namespace gridcull {

namespace {

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec4 a_color;
uniform mat4 u_view_projection;
out vec4 v_color;
void main() {
    v_color = a_color;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
)";

const char* const kFragmentShader = R"(#version 330 core
in vec4 v_color;
out vec4 frag_color;
void main() { frag_color = v_color; }
)";

}  // namespace

bool LineRenderer::init(std::string& error) {
    program_ = buildGlProgram(kVertexShader, kFragmentShader, error);
    if (!program_.get()) return false;
    view_projection_location_ = glGetUniformLocation(program_.get(), "u_view_projection");
    vao_ = makeGlVertexArray();
    vertices_.init(GL_ARRAY_BUFFER);
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<const void*>(offsetof(ColorVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(ColorVertex),
                          reinterpret_cast<const void*>(offsetof(ColorVertex, color)));
    glBindVertexArray(0);
    GLfloat range[2] = {1.0f, 1.0f};
    glGetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, range);
    max_width_ = std::max(range[1], 1.0f);
    return true;
}

void LineRenderer::draw(const std::vector<ColorVertex>& vertices, GLenum mode,
                        const glm::mat4& view_projection, float width, bool depth_test) {
    if (vertices.empty()) return;
    glUseProgram(program_.get());
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    glBindVertexArray(vao_.get());
    vertices_.upload(vertices.data(), vertices.size() * sizeof(ColorVertex));
    if (depth_test) glEnable(GL_DEPTH_TEST); else glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    // Destination alpha stays 1, so read-back images are opaque.
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_CULL_FACE);
    glLineWidth(std::min(width, max_width_));
    glDrawArrays(mode, 0, GLsizei(vertices.size()));
    glLineWidth(1.0f);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
}

}  // namespace gridcull
