// The scene view's overlays (Renderer::drawOverlays): world box, 2D grid, the
// culling camera's frustum or wedge, outlines of false-culled, compared-differing
// and hovered objects.
#include <algorithm>

#include "app/renderer.h"

namespace gridcull {

namespace {

const glm::vec4 kWorldFill = toRgba(worldFillColor());
const glm::vec4 kWorldEdge(0.50f, 0.52f, 0.56f, 1.0f);
const glm::vec4 kGridLine(0.24f, 0.25f, 0.28f, 1.0f);
const glm::vec4 kHover(1.0f, 1.0f, 1.0f, 1.0f);
constexpr float kHighlightWidth = 3.0f;
// Comparing two cullers, objects in one PVS only are outlined while there are
// at most this many; more outlines would hide the scene (the fade still shows them).
constexpr size_t kMaxDifferenceOutlines = 200;
constexpr float kFrustumWidth = 2.0f;
// The smallest on-screen voxel, in pixels, for which the 2D grid is drawn.
constexpr double kMinGridPixels = 6.0;

}  // namespace

void Renderer::drawOverlays(const SceneDrawInput& input, bool under_objects) {
    const Scene& scene = *input.scene;
    const glm::mat4 view_projection(input.view.view_projection);
    const Camera& camera = input.culling_camera;
    const glm::vec4 camera_color = toRgba(cullingCameraColor());
    const double reach = viewDrawDistance(camera, scene.grid.world);
    lines_.clear();
    fill_.clear();
    highlight_.clear();

    if (dimensions_ == 2) {
        if (under_objects) {
            const Aabb& w = scene.grid.world;
            const glm::dvec3 corners[4] = {{w.min.x, w.min.y, 0}, {w.max.x, w.min.y, 0},
                                           {w.max.x, w.max.y, 0}, {w.min.x, w.max.y, 0}};
            for (int k : {0, 1, 2, 0, 2, 3}) fill_.push_back({glm::vec3(corners[k]), kWorldFill});
            line_renderer_.draw(fill_, GL_TRIANGLES, view_projection, 1.0f, false);
            fill_.clear();
            const glm::dvec3 voxel = scene.grid.voxelSize();
            const double pixels_per_unit =
                input.viewport.height / (2.0 / input.view.projection[1][1]);
            if (std::min(voxel.x, voxel.y) * pixels_per_unit >= kMinGridPixels)
                appendGridLines2d(lines_, scene.grid, kGridLine);
            appendBoxEdges(lines_, w, kWorldEdge);
            line_renderer_.draw(lines_, GL_LINES, view_projection, 1.0f, false);
            lines_.clear();
            if (input.show_culling_camera) {
                appendWedge(lines_, fill_, camera, reach, camera_color,
                            glm::vec4(glm::vec3(camera_color), 0.10f));
                line_renderer_.draw(fill_, GL_TRIANGLES, view_projection, 1.0f, false);
            }
            return;
        }
        if (input.show_culling_camera)
            appendWedge(lines_, fill_, camera, reach, camera_color, glm::vec4(0.0f));
        line_renderer_.draw(lines_, GL_LINES, view_projection, kFrustumWidth, false);
    } else {
        if (under_objects) return;
        appendBoxEdges(lines_, scene.grid.world, kWorldEdge);
        if (input.show_culling_camera) appendFrustum(lines_, camera, scene.grid.world, camera_color);
        // Once faintly through everything, once depth-tested at full strength: the
        // frustum stays findable behind objects and still reads as being in 3D.
        for (ColorVertex& v : lines_) v.color.a *= 0.3f;
        line_renderer_.draw(lines_, GL_LINES, view_projection, kFrustumWidth, false);
        for (ColorVertex& v : lines_) v.color.a /= 0.3f;
        line_renderer_.draw(lines_, GL_LINES, view_projection, kFrustumWidth, true);
    }

    // False culls and the hovered object: outlines over everything, so one wrong
    // object shows even in a still image of a crowded scene.
    // Differences between compared cullers first, so a false cull's outline
    // stays on top of them. Each is outlined in its own state's colour, which
    // the faded objects around it lack: no colour of the palette is spent on it.
    const std::vector<ObjectState>& states = *input.states;
    if (input.differing && input.differing->size() <= kMaxDifferenceOutlines) {
        for (int i : *input.differing) {
            if (i < 0 || size_t(i) >= scene.objects.size() || size_t(i) >= states.size()) continue;
            const glm::vec4 color = toRgba(objectStateColor(states[size_t(i)]));
            if (dimensions_ == 2)
                appendOutline2d(highlight_, scene, scene.objects[size_t(i)], input.t, color);
            else
                appendBoxEdges(highlight_, scene.boundsAt(scene.objects[size_t(i)], input.t),
                               color);
        }
    }
    const glm::vec4 false_color = toRgba(objectStateColor(ObjectState::FalseCulled));
    for (size_t i = 0; i < scene.objects.size() && i < states.size(); ++i) {
        if (states[i] != ObjectState::FalseCulled) continue;
        if (dimensions_ == 2)
            appendOutline2d(highlight_, scene, scene.objects[i], input.t, false_color);
        else
            appendBoxEdges(highlight_, scene.boundsAt(scene.objects[i], input.t), false_color);
    }
    line_renderer_.draw(highlight_, GL_LINES, view_projection, kHighlightWidth, false);
    highlight_.clear();
    if (input.hovered_index >= 0 && input.hovered_index < int(scene.objects.size())) {
        const SceneObject& object = scene.objects[size_t(input.hovered_index)];
        if (dimensions_ == 2)
            appendOutline2d(highlight_, scene, object, input.t, kHover);
        else
            appendBoxEdges(highlight_, scene.boundsAt(object, input.t), kHover);
        line_renderer_.draw(highlight_, GL_LINES, view_projection, 2.0f, false);
    }
}

}  // namespace gridcull
