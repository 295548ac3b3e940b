#include "app/gl_debug_draw.h"

#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

// stb_easy_font is a header of static functions; not every one is used here.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace gridcull {

namespace {

// stb_easy_font's vertex: x, y, z as floats, then RGBA bytes; four per quad.
struct GlyphVertex {
    float x, y, z;
    unsigned char rgba[4];
};
static_assert(sizeof(GlyphVertex) == 16, "stb_easy_font writes 16-byte vertices");

constexpr float kShadowAlpha = 0.8f;

}  // namespace

void GlDebugDraw::appendLabel(const DebugDrawBatch::Label& label, const glm::vec2& at) {
    // Glyphs are drawn for printable ASCII only; anything else shows as '?'.
    label_.assign(batch_.texts(), label.text_begin, label.text_end - label.text_begin);
    for (char& c : label_)
        if (c < 32 || c > 126) c = '?';
    // About 270 bytes per character, as stb_easy_font's header says.
    glyphs_.resize(label_.size() * 300 + 64);
    const int quads = stb_easy_font_print(0.0f, 0.0f, label_.data(), nullptr, glyphs_.data(),
                                          int(glyphs_.size()));
    const Rgb c = swatchColor(label.paint.swatch);
    const glm::vec4 color(c.r, c.g, c.b, label.paint.alpha);
    const glm::vec4 shadow(0.0f, 0.0f, 0.0f, kShadowAlpha * label.paint.alpha);
    const float s = label.scale;
    for (const glm::vec4* paint : {&shadow, &color}) {
        const glm::vec2 origin = at + (paint == &shadow ? glm::vec2(1.0f) : glm::vec2(0.0f));
        for (int q = 0; q < quads; ++q) {
            GlyphVertex v[4];
            std::memcpy(v, glyphs_.data() + size_t(q) * sizeof v, sizeof v);
            glm::vec3 p[4];
            for (int k = 0; k < 4; ++k)
                p[k] = glm::vec3(origin + s * glm::vec2(v[k].x, v[k].y), 0.0f);
            for (int k : {0, 1, 2, 0, 2, 3}) text_.push_back({p[k], *paint});
        }
    }
}

void GlDebugDraw::flush(const glm::mat4& view_projection, int view_width, int view_height) {
    // View pixels, origin top left, onto the current viewport.
    const glm::mat4 pixels = glm::ortho(0.0f, float(view_width), float(view_height), 0.0f);
    for (const DrawSpace space : {DrawSpace::World, DrawSpace::View}) {
        const DebugDrawBatch::Layer& layer = batch_.layer(space);
        const glm::mat4& matrix = space == DrawSpace::World ? view_projection : pixels;
        lines_.draw(layer.fill, GL_TRIANGLES, matrix, 1.0f, false);
        for (const DebugDrawBatch::LineSet& set : layer.lines)
            lines_.draw(set.vertices, GL_LINES, matrix, set.width, false);
        text_.clear();
        for (const DebugDrawBatch::Label& label : layer.labels) {
            glm::vec2 at(label.at);
            if (space == DrawSpace::World) {
                const glm::vec4 clip = view_projection * glm::vec4(glm::vec3(label.at), 1.0f);
                if (clip.w <= 0.0f) continue;  // behind the view's camera
                at = {(clip.x / clip.w + 1.0f) * 0.5f * float(view_width),
                      (1.0f - clip.y / clip.w) * 0.5f * float(view_height)};
            }
            appendLabel(label, at);
        }
        lines_.draw(text_, GL_TRIANGLES, pixels, 1.0f, false);
    }
    batch_.clear();
}

}  // namespace gridcull
