// The scene view: every object of the scene drawn at time t, coloured by its
// culling state, and the overlays (world box, 2D grid, the culling camera's
// frustum or wedge, outlines of false-culled and hovered objects).
//
// 3D: spheres are instances of a tessellated unit sphere at one of four levels
// of detail chosen by projected size, boxes instances of one unit cube
// (per-instance centre, size, colour); each distinct mesh has its own vertex
// range, drawn instanced over the objects that share it. Lit by a headlight plus
// a sky term. 2D: a top-down map; circles are unit discs, boxes unit squares,
// polygons triangulated by ear clipping once per scene; flat colours, with the
// states layered in depth so a false cull is never hidden under a culled shape.
// Over the objects and under the outlines, the selected family's overlay
// (ui/family_view.h), drawn through the debug-draw interface (app/gl_debug_draw.h).
// Looking through the culling camera, what lies outside its image (the bars a
// view of another aspect shows beside it) is dimmed: no culler saw it.
//
// All buffers are sized on setScene() and reused: a steady state allocates
// nothing per frame. Needs a current GL 3.3 core context for every call.
#pragma once
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "app/gl_debug_draw.h"
#include "app/gl_objects.h"
#include "app/line_renderer.h"
#include "app/view_camera.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"
#include "ui/family_view.h"
#include "ui/layout.h"
#include "ui/object_state.h"

namespace gridcull {

struct SceneDrawInput {
    const Scene* scene = nullptr;
    double t = 0.0;
    const std::vector<ObjectState>* states = nullptr;  // by object index
    Camera culling_camera;
    bool show_culling_camera = true;  // off when looking through it
    ViewMatrices view;
    WindowRect viewport;                  // framebuffer pixels, origin top left
    int framebuffer_height = 0;           // to flip the viewport into GL's bottom-left origin
    int hovered_index = -1;               // outlined when >= 0
    // Comparing two cullers: the objects (indices) in one PVS only, drawn in
    // full colour (and outlined while there are few) with every other object
    // faded; null when not comparing.
    const std::vector<int>* differing = nullptr;
    bool through_culling_camera = false;  // 3D, the view is the culling camera's
    // The selected family's view, which draws its overlay (null: none), and the
    // frame as it sees it.
    FamilyView* family = nullptr;
    const FamilyViewContext* family_context = nullptr;
    // What an application would draw: only the objects in the PVS (state
    // Visible or Hidden), no overlay, outline or camera (bench --draw).
    bool pvs_only = false;
};

class Renderer {
public:
    bool init(std::string& error);
    // Builds the vertex data of `scene` (meshes, polygons) and the draw groups.
    // Call again whenever the scene changes. Cost: O(scene geometry).
    void setScene(const Scene& scene);
    // Draws into the bound framebuffer, inside input.viewport only. Returns the CPU
    // milliseconds from the first GL call to the end of glFinish, so frame times
    // of different scenes and algorithms compare.
    double draw(const SceneDrawInput& input);

private:
    struct Instance {
        glm::vec3 offset;
        glm::vec3 scale;
        glm::vec4 color;
    };
    static constexpr int kSphereLods = 4;
    struct SphereLod {
        size_t index_offset = 0;  // bytes into the sphere index buffer
        GLsizei index_count = 0;
    };
    struct DrawGroup {
        bool sphere = false;  // the indexed unit spheres; else a soup range
        GLint first = 0;      // soup: first vertex
        GLsizei count = 0;    // soup: vertex count
        bool cull_back_faces = false;
        std::vector<int> objects;  // indices into scene.objects
        size_t instance_first = 0;
        size_t instance_count = 0;  // this frame: all objects, or those in the PVS
        size_t lod_count[kSphereLods] = {};  // sphere: instances per level, in order
    };

    void buildInstances(const SceneDrawInput& input);
    void buildSphereInstances(const SceneDrawInput& input, DrawGroup& group);
    Instance makeInstance(const SceneDrawInput& input, int index) const;
    bool drawn(const SceneDrawInput& input, int index) const;
    void drawObjects(const SceneDrawInput& input);
    void drawOverlays(const SceneDrawInput& input, bool under_objects);
    void bindInstanceAttributes(size_t first_instance) const;
    void dimOutsideCullingImage(const SceneDrawInput& input);

    GlProgram program_;
    GLint view_projection_location_ = -1;
    GLint eye_location_ = -1;
    GLint flat_location_ = -1;
    GlVertexArray sphere_vao_;
    GlBuffer sphere_vertices_;
    GlBuffer sphere_indices_;
    SphereLod sphere_lods_[kSphereLods];
    std::vector<uint8_t> sphere_lod_;  // per sphere of the group, this frame
    std::vector<uint8_t> differs_;     // per object: in input.differing, this frame
    GlVertexArray soup_vao_;
    GlBuffer soup_vertices_;
    StreamBuffer instance_buffer_;

    int dimensions_ = 3;
    std::vector<DrawGroup> groups_;
    std::vector<Instance> instances_;
    std::vector<ColorVertex> lines_;
    std::vector<ColorVertex> fill_;
    std::vector<ColorVertex> highlight_;
    LineRenderer line_renderer_;
    GlDebugDraw debug_draw_;
};

}  // namespace gridcull
