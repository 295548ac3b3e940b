#include "app/renderer.h"

#include <chrono>
#include <cstddef>
#include <unordered_map>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/shape_geometry.h"

namespace gridcull {

namespace {

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 i_offset;
layout(location = 3) in vec3 i_scale;
layout(location = 4) in vec4 i_color;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
out vec4 v_color;
void main() {
    vec3 world = i_offset + i_scale * a_position;
    v_world = world;
    // Inverse-transpose of a diagonal scale; unit shapes only ever scale positively.
    v_normal = a_normal / max(i_scale, vec3(1e-6));
    v_color = i_color;
    gl_Position = u_view_projection * vec4(world, 1.0);
}
)";

// A headlight (so whatever the view faces is lit) plus a sky term (so tops and
// bottoms differ and shapes read as solids), over an ambient floor that keeps
// culled grey objects visible against the background.
const char* const kFragmentShader = R"(#version 330 core
in vec3 v_world;
in vec3 v_normal;
in vec4 v_color;
uniform vec3 u_eye;
uniform int u_flat;
out vec4 frag_color;
void main() {
    if (u_flat != 0) {
        frag_color = vec4(v_color.rgb, 1.0);
        return;
    }
    vec3 n = normalize(v_normal);
    float head = abs(dot(n, normalize(u_eye - v_world)));
    float sky = 0.5 + 0.5 * n.y;
    float shade = 0.35 + 0.55 * head + 0.25 * sky;
    frag_color = vec4(min(v_color.rgb * shade, vec3(1.0)), 1.0);
}
)";

// Sphere levels of detail (slices, stacks) and the projected radius in pixels
// from which each is used; small far spheres are most of a cluster scene, and
// llvmpipe's cost follows the triangle count.
constexpr int kSphereSlices[4] = {32, 16, 10, 6};
constexpr int kSphereStacks[4] = {16, 8, 5, 3};
constexpr double kSphereLodPixels[4] = {24.0, 10.0, 4.0, 0.0};
constexpr int kDiscSegments = 40;
const glm::vec4 kBackground = toRgba(viewBackgroundColor());
// Comparing two cullers, how far objects in both PVS or neither fade towards
// the background, so the few that differ stand out in their state's colour.
constexpr float kSameInBothFade = 0.7f;
// Opacity of the veil over what lies outside the culling camera's image.
constexpr float kOutsideImageVeil = 0.6f;

// 2D depth layer: higher states are drawn over lower ones.
float layerDepth(ObjectState state) {
    switch (state) {
        case ObjectState::Culled:
            return 0.1f;
        case ObjectState::Hidden:
            return 0.2f;
        case ObjectState::Visible:
            return 0.3f;
        case ObjectState::SubSample:
            return 0.35f;
        case ObjectState::FalseCulled:
            return 0.4f;
    }
    return 0.1f;
}

void setShadedLayout() {
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(ShadedVertex),
                          reinterpret_cast<const void*>(offsetof(ShadedVertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(ShadedVertex),
                          reinterpret_cast<const void*>(offsetof(ShadedVertex, normal)));
    for (GLuint attribute = 2; attribute <= 4; ++attribute) {
        glEnableVertexAttribArray(attribute);
        glVertexAttribDivisor(attribute, 1);
    }
}

}  // namespace

bool Renderer::init(std::string& error) {
    program_ = buildGlProgram(kVertexShader, kFragmentShader, error);
    if (!program_.get()) return false;
    view_projection_location_ = glGetUniformLocation(program_.get(), "u_view_projection");
    eye_location_ = glGetUniformLocation(program_.get(), "u_eye");
    flat_location_ = glGetUniformLocation(program_.get(), "u_flat");
    if (!line_renderer_.init(error) || !debug_draw_.init(error)) return false;

    std::vector<ShadedVertex> vertices, lod_vertices;
    std::vector<uint32_t> indices, lod_indices;
    for (int lod = 0; lod < kSphereLods; ++lod) {
        buildUnitSphere(kSphereSlices[lod], kSphereStacks[lod], lod_vertices, lod_indices);
        const uint32_t base = uint32_t(vertices.size());
        sphere_lods_[lod].index_offset = indices.size() * sizeof(uint32_t);
        sphere_lods_[lod].index_count = GLsizei(lod_indices.size());
        for (uint32_t i : lod_indices) indices.push_back(base + i);
        vertices.insert(vertices.end(), lod_vertices.begin(), lod_vertices.end());
    }
    sphere_vao_ = makeGlVertexArray();
    sphere_vertices_ = makeGlBuffer();
    sphere_indices_ = makeGlBuffer();
    glBindVertexArray(sphere_vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, sphere_vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(vertices.size() * sizeof(ShadedVertex)),
                 vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphere_indices_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    setShadedLayout();

    soup_vao_ = makeGlVertexArray();
    soup_vertices_ = makeGlBuffer();
    glBindVertexArray(soup_vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, soup_vertices_.get());
    setShadedLayout();
    glBindVertexArray(0);

    instance_buffer_.init(GL_ARRAY_BUFFER);
    const GLenum status = glGetError();
    if (status != GL_NO_ERROR) {
        error = "OpenGL error " + std::to_string(status) + " while setting up the renderer";
        return false;
    }
    return true;
}

void Renderer::setScene(const Scene& scene) {
    dimensions_ = scene.dimensions;
    groups_.clear();
    std::vector<ShadedVertex> soup;
    auto range = [&](auto&& append, bool cull) {
        DrawGroup group;
        group.first = GLint(soup.size());
        append();
        group.count = GLsizei(soup.size()) - group.first;
        group.cull_back_faces = cull;
        groups_.push_back(std::move(group));
        return groups_.size() - 1;
    };

    size_t round_group = 0, box_group = 0;
    if (dimensions_ == 3) {
        DrawGroup spheres;
        spheres.sphere = true;
        spheres.cull_back_faces = true;
        groups_.push_back(std::move(spheres));
        round_group = 0;
        box_group = range([&] { appendUnitCube(soup); }, true);
    } else {
        round_group = range([&] { appendUnitDisc(kDiscSegments, soup); }, false);
        box_group = range([&] { appendUnitSquare(soup); }, false);
    }
    std::unordered_map<const TriangleMesh*, size_t> mesh_groups;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        size_t group = 0;
        switch (object.shape) {
            case ShapeKind::Sphere:
                group = round_group;
                break;
            case ShapeKind::Box:
                group = box_group;
                break;
            case ShapeKind::Mesh: {
                const auto found = mesh_groups.find(object.mesh.get());
                if (found != mesh_groups.end()) {
                    group = found->second;
                } else {
                    group = range([&] { appendMesh(*object.mesh, soup); }, false);
                    mesh_groups.emplace(object.mesh.get(), group);
                }
                break;
            }
            case ShapeKind::Polygon:
                // The loader only accepts simple polygons (culling/scene/polygon2d.h), for
                // which ear clipping always completes.
                group = range([&] { appendPolygon(object, soup); }, false);
                break;
        }
        groups_[group].objects.push_back(int(i));
    }
    glBindBuffer(GL_ARRAY_BUFFER, soup_vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(soup.size() * sizeof(ShadedVertex)), soup.data(),
                 GL_STATIC_DRAW);
    instances_.reserve(scene.objects.size());
    differs_.reserve(scene.objects.size());
    sphere_lod_.reserve(groups_.empty() ? 0 : groups_[0].objects.size());
}

Renderer::Instance Renderer::makeInstance(const SceneDrawInput& input, int index) const {
    const Scene& scene = *input.scene;
    const SceneObject& object = scene.objects[size_t(index)];
    const std::vector<ObjectState>& states = *input.states;
    const ObjectState state =
        size_t(index) < states.size() ? states[size_t(index)] : ObjectState::Culled;
    const glm::dvec3 d = scene.displacementAt(object, input.t);
    Instance instance;
    instance.color = toRgba(objectStateColor(state));
    if (input.differing && !differs_[size_t(index)])
        instance.color = glm::mix(instance.color, kBackground, kSameInBothFade);
    switch (object.shape) {
        case ShapeKind::Sphere:
            instance.offset = glm::vec3(object.center + d);
            instance.scale = glm::vec3(float(object.radius));
            break;
        case ShapeKind::Box:
            instance.offset = glm::vec3(object.box.center() + d);
            instance.scale = glm::vec3(object.box.extent());
            break;
        case ShapeKind::Mesh:
            instance.offset = glm::vec3(object.center + d);
            instance.scale = glm::vec3(1.0f);
            break;
        case ShapeKind::Polygon:
            instance.offset = glm::vec3(object.anchor + d);
            instance.scale = glm::vec3(1.0f);
            break;
    }
    if (dimensions_ == 2) {
        instance.offset.z = layerDepth(state);
        instance.scale.z = 1.0f;
    }
    return instance;
}

bool Renderer::drawn(const SceneDrawInput& input, int index) const {
    if (!input.pvs_only) return true;
    const std::vector<ObjectState>& states = *input.states;
    if (size_t(index) >= states.size()) return false;
    return states[size_t(index)] == ObjectState::Visible ||
           states[size_t(index)] == ObjectState::Hidden;
}

void Renderer::buildSphereInstances(const SceneDrawInput& input, DrawGroup& group) {
    const ViewMatrices& view = input.view;
    // Pixels per world unit at unit view depth.
    const double pixels = 0.5 * input.viewport.height * view.projection[1][1];
    // The level of each sphere drawn, and kSphereLods for one not drawn.
    sphere_lod_.resize(group.objects.size());
    for (size_t& count : group.lod_count) count = 0;
    for (size_t k = 0; k < group.objects.size(); ++k) {
        if (!drawn(input, group.objects[k])) {
            sphere_lod_[k] = uint8_t(kSphereLods);
            continue;
        }
        const SceneObject& object = input.scene->objects[size_t(group.objects[k])];
        const glm::dvec3 c = object.center + input.scene->displacementAt(object, input.t);
        const double depth = glm::dot(c - view.eye, view.forward);
        const double radius_pixels =
            depth > object.radius ? object.radius * pixels / depth : kSphereLodPixels[0];
        int lod = 0;
        while (lod + 1 < kSphereLods && radius_pixels < kSphereLodPixels[lod]) ++lod;
        sphere_lod_[k] = uint8_t(lod);
        ++group.lod_count[lod];
    }
    size_t cursor[kSphereLods];
    cursor[0] = instances_.size();
    for (int lod = 1; lod < kSphereLods; ++lod)
        cursor[lod] = cursor[lod - 1] + group.lod_count[lod - 1];
    group.instance_count = 0;
    for (size_t count : group.lod_count) group.instance_count += count;
    instances_.resize(instances_.size() + group.instance_count);
    for (size_t k = 0; k < group.objects.size(); ++k)
        if (sphere_lod_[k] < kSphereLods)
            instances_[cursor[sphere_lod_[k]]++] = makeInstance(input, group.objects[k]);
}

void Renderer::buildInstances(const SceneDrawInput& input) {
    instances_.clear();
    for (DrawGroup& group : groups_) {
        group.instance_first = instances_.size();
        if (group.sphere) {
            buildSphereInstances(input, group);
            continue;
        }
        for (int index : group.objects)
            if (drawn(input, index)) instances_.push_back(makeInstance(input, index));
        group.instance_count = instances_.size() - group.instance_first;
    }
}

void Renderer::bindInstanceAttributes(size_t first_instance) const {
    glBindBuffer(GL_ARRAY_BUFFER, instance_buffer_.id());
    const size_t base = first_instance * sizeof(Instance);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(base + offsetof(Instance, offset)));
    glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(base + offsetof(Instance, scale)));
    glVertexAttribPointer(4, 4, GL_FLOAT, GL_FALSE, sizeof(Instance),
                          reinterpret_cast<const void*>(base + offsetof(Instance, color)));
}

void Renderer::drawObjects(const SceneDrawInput& input) {
    buildInstances(input);
    instance_buffer_.upload(instances_.data(), instances_.size() * sizeof(Instance));
    glUseProgram(program_.get());
    const glm::mat4 view_projection(input.view.view_projection);
    glUniformMatrix4fv(view_projection_location_, 1, GL_FALSE, glm::value_ptr(view_projection));
    const glm::vec3 eye(input.view.eye);
    glUniform3fv(eye_location_, 1, glm::value_ptr(eye));
    glUniform1i(flat_location_, dimensions_ == 2 ? 1 : 0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    for (const DrawGroup& group : groups_) {
        const GLsizei count = GLsizei(group.instance_count);
        if (count == 0) continue;
        if (group.cull_back_faces)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        if (group.sphere) {
            glBindVertexArray(sphere_vao_.get());
            size_t first = group.instance_first;
            for (int lod = 0; lod < kSphereLods; ++lod) {
                if (group.lod_count[lod] == 0) continue;
                bindInstanceAttributes(first);
                glDrawElementsInstanced(
                    GL_TRIANGLES, sphere_lods_[lod].index_count, GL_UNSIGNED_INT,
                    reinterpret_cast<const void*>(sphere_lods_[lod].index_offset),
                    GLsizei(group.lod_count[lod]));
                first += group.lod_count[lod];
            }
        } else {
            glBindVertexArray(soup_vao_.get());
            bindInstanceAttributes(group.instance_first);
            glDrawArraysInstanced(GL_TRIANGLES, group.first, group.count, count);
        }
    }
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

void Renderer::dimOutsideCullingImage(const SceneDrawInput& input) {
    const WindowRect& r = input.viewport;
    const ViewRect image =
        cullingImageFrame(input.culling_camera.aspect, r.width, r.height, 1, 1).area;
    const Paint veil{Swatch::NearBlack, kOutsideImageVeil};
    DebugDrawBatch& batch = debug_draw_.batch();
    batch.clear();
    batch.fillRect({0.0, 0.0, double(r.width), image.y0}, veil);
    batch.fillRect({0.0, image.y1, double(r.width), double(r.height)}, veil);
    batch.fillRect({0.0, image.y0, image.x0, image.y1}, veil);
    batch.fillRect({image.x1, image.y0, double(r.width), image.y1}, veil);
    debug_draw_.flush(glm::mat4(input.view.view_projection), r.width, r.height);
}

double Renderer::draw(const SceneDrawInput& input) {
    const auto start = std::chrono::steady_clock::now();
    const WindowRect& r = input.viewport;
    const GLint gl_y = input.framebuffer_height - (r.y + r.height);
    glViewport(r.x, gl_y, r.width, r.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, gl_y, r.width, r.height);
    glClearColor(kBackground.r, kBackground.g, kBackground.b, kBackground.a);
    glClearDepth(1.0);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    if (input.differing) {
        differs_.assign(input.scene->objects.size(), 0);
        for (int i : *input.differing)
            if (i >= 0 && size_t(i) < differs_.size()) differs_[size_t(i)] = 1;
    }
    if (!input.pvs_only) drawOverlays(input, true);
    drawObjects(input);
    // Over the objects, under the overlay (whose panels, a Z-pyramid say, may
    // sit in the bars).
    if (input.through_culling_camera) dimOutsideCullingImage(input);
    if (input.family && input.family_context && !input.pvs_only) {
        // Under the outlines of false culls, which must stay findable.
        OverlayView view;
        view.view_projection = input.view.view_projection;
        view.width = r.width;
        view.height = r.height;
        view.through_culling_camera = input.through_culling_camera;
        view.culling_aspect = input.culling_camera.aspect;
        view.culling_camera = input.culling_camera;
        debug_draw_.batch().clear();
        input.family->drawOverlay(*input.family_context, view, debug_draw_.batch());
        debug_draw_.flush(glm::mat4(input.view.view_projection), r.width, r.height);
    }
    if (!input.pvs_only) drawOverlays(input, false);

    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glFinish();
    const auto end = std::chrono::steady_clock::now();
    return std::chrono::duration<double, std::milli>(end - start).count();
}

}  // namespace gridcull
