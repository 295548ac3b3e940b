#include "app/gl_image_target.h"

#include <algorithm>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "app/shape_geometry.h"

namespace gridcull {

namespace {

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 a_position;
uniform mat4 u_mvp;
void main() { gl_Position = u_mvp * vec4(a_position, 1.0); }
)";

const char* const kFragmentShader = R"(#version 330 core
out vec4 frag_color;
void main() { frag_color = vec4(1.0); }
)";

constexpr int kSphereSlices = 32, kSphereStacks = 16;  // object_triangles.h's count

}  // namespace

GlImageTarget::Mesh GlImageTarget::upload(const std::vector<float>& positions,
                                          const std::vector<uint32_t>& indices) {
    Mesh mesh;
    mesh.vao = makeGlVertexArray();
    mesh.vertices = makeGlBuffer();
    mesh.indices = makeGlBuffer();
    glBindVertexArray(mesh.vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, mesh.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(positions.size() * sizeof(float)), positions.data(),
                 GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(indices.size() * sizeof(uint32_t)),
                 indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glBindVertexArray(0);
    mesh.index_count = int(indices.size());
    return mesh;
}

bool GlImageTarget::init(std::string& error) {
    program_ = buildGlProgram(kVertexShader, kFragmentShader, error);
    if (!program_.get()) return false;
    mvp_location_ = glGetUniformLocation(program_.get(), "u_mvp");
    std::vector<ShadedVertex> shaded;
    std::vector<uint32_t> indices;
    buildUnitSphere(kSphereSlices, kSphereStacks, shaded, indices);
    std::vector<float> positions;
    for (const ShadedVertex& v : shaded)
        positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
    sphere_ = upload(positions, indices);
    shaded.clear();
    appendUnitCube(shaded);
    positions.clear();
    indices.clear();
    for (const ShadedVertex& v : shaded) {
        indices.push_back(uint32_t(indices.size()));
        positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
    }
    cube_ = upload(positions, indices);
    return true;
}

GlImageTarget::~GlImageTarget() {
    for (int s = 0; s < queries_.capacity(); ++s) {
        GLuint& name = queries_.slotPayload(s).name;
        if (name) glDeleteQueries(1, &name);
        name = 0;
    }
}

void GlImageTarget::makeQueryObjects() {
    for (int s = 0; s < queries_.capacity(); ++s) {
        GLuint& name = queries_.slotPayload(s).name;
        if (!name) glGenQueries(1, &name);
    }
}

void GlImageTarget::prepare(const Scene& scene) {
    queries_.reserve(kOcclusionQueryReserve);
    queries_.releaseAll();
    makeQueryObjects();
    counts_ = {};
    meshes_.clear();
    triangle_sets_.clear();
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh || meshes_.count(object.mesh.get())) continue;
        std::vector<float> positions;
        for (const glm::dvec3& v : object.mesh->vertices)
            positions.insert(positions.end(), {float(v.x), float(v.y), float(v.z)});
        meshes_.emplace(object.mesh.get(), upload(positions, object.mesh->indices));
    }
}

void GlImageTarget::begin(const Camera& camera, int width, int height, bool) {
    if (framebuffer_.width() != width || framebuffer_.height() != height) {
        std::string error;
        framebuffer_.create(width, height, error);
        depth_.assign(size_t(width) * size_t(height), 0.0f);
    }
    height_ = height;
    camera_ = camera;
    near_ = camera.near;
    far_ = camera.far;
    view_projection_ = glm::mat4(camera.projectionMatrix() * camera.viewMatrix());
    framebuffer_.bind();
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_CULL_FACE);  // two-sided, as the oracle
    glDisable(GL_BLEND);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearDepth(1.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glUseProgram(program_.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
}

void GlImageTarget::drawMesh(const Mesh& mesh, const glm::mat4& model) {
    const glm::mat4 mvp = view_projection_ * model;
    glUniformMatrix4fv(mvp_location_, 1, GL_FALSE, glm::value_ptr(mvp));
    glBindVertexArray(mesh.vao.get());
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
}

bool GlImageTarget::draw(const SceneObject& object, int, const glm::dvec3& shift,
                         const PixelRect& image_area, PixelRect& written) {
    switch (object.shape) {
        case ShapeKind::Sphere: {
            const glm::dvec3 c = object.center + shift;
            drawMesh(sphere_, glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(c)),
                                         glm::vec3(float(object.radius))));
            break;
        }
        case ShapeKind::Box: {
            const Aabb box = object.box.translated(shift);
            drawMesh(cube_, glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(box.center())),
                                       glm::vec3(box.extent())));
            break;
        }
        case ShapeKind::Mesh: {
            const auto found = meshes_.find(object.mesh.get());
            if (found == meshes_.end()) return false;
            drawMesh(found->second,
                     glm::translate(glm::mat4(1.0f), glm::vec3(object.center + shift)));
            break;
        }
        case ShapeKind::Polygon:
            return false;
    }
    written = image_area;
    return !image_area.empty();
}

int GlImageTarget::addTriangleSet(const std::vector<glm::dvec3>& corners) {
    TriangleSet set;
    set.vao = makeGlVertexArray();
    set.vertices = makeGlBuffer();
    std::vector<float> positions;
    positions.reserve(corners.size() * 3);
    for (const glm::dvec3& v : corners)
        positions.insert(positions.end(), {float(v.x), float(v.y), float(v.z)});
    glBindVertexArray(set.vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, set.vertices.get());
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(positions.size() * sizeof(float)), positions.data(),
                 GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), nullptr);
    glBindVertexArray(0);
    set.triangle_count = int(corners.size() / 3);
    triangle_sets_.push_back(std::move(set));
    return int(triangle_sets_.size()) - 1;
}

bool GlImageTarget::drawTriangles(int handle, int first, int count, int, const glm::dvec3& shift,
                                  const PixelRect& image_area, PixelRect& written) {
    if (handle < 0 || size_t(handle) >= triangle_sets_.size() || count <= 0) return false;
    const TriangleSet& set = triangle_sets_[size_t(handle)];
    if (first < 0 || first + count > set.triangle_count) return false;
    const glm::mat4 mvp = view_projection_ * glm::translate(glm::mat4(1.0f), glm::vec3(shift));
    glUniformMatrix4fv(mvp_location_, 1, GL_FALSE, glm::value_ptr(mvp));
    glBindVertexArray(set.vao.get());
    glDrawArrays(GL_TRIANGLES, 3 * first, 3 * count);
    written = image_area;
    return !image_area.empty();
}

size_t GlImageTarget::readDepths(const PixelRect& rect) const {
    const int w = rect.x1 - rect.x0 + 1, h = rect.y1 - rect.y0 + 1;
    // GL's row 0 is the bottom of the image.
    glReadPixels(rect.x0, height_ - 1 - rect.y1, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depth_.data());
    return size_t(w) * size_t(h);
}

long long GlImageTarget::countFree(const PixelRect& rect) const {
    const size_t n = readDepths(rect);
    return std::count(depth_.begin(), depth_.begin() + long(n), 1.0f);
}

double GlImageTarget::farthestDepth(const PixelRect& rect) const {
    const size_t n = readDepths(rect);
    const float d = *std::max_element(depth_.begin(), depth_.begin() + long(n));
    // One 24-bit step farther, so that rounding never puts a pixel nearer.
    const double far_side = double(d) + 1.0 / 16777215.0;
    if (d >= 1.0f || far_side >= 1.0) return std::numeric_limits<double>::infinity();
    // Window depth [0, 1] back to view-space distance (OpenGL's perspective).
    const double z_ndc = 2.0 * far_side - 1.0;
    return 2.0 * far_ * near_ / (far_ + near_ - z_ndc * (far_ - near_));
}

void GlImageTarget::end() {
    glFinish();
}

OcclusionQuery GlImageTarget::issueQuery(const Aabb& box) {
    const OcclusionQuery query = queries_.acquire();
    GlQuery& q = queries_.payload(query);
    ++counts_.issued;
    q.trivial = occlusionQueryTriviallyVisible(camera_, box);
    if (q.trivial) {
        ++counts_.trivial;
        return query;
    }
    if (!q.name) glGenQueries(1, &q.name);  // a slot the pool has just added
    glDepthMask(GL_FALSE);                  // colour writes are off since begin()
    glBeginQuery(GL_ANY_SAMPLES_PASSED, q.name);
    drawMesh(cube_, glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(box.center())),
                               glm::vec3(box.extent())));
    glEndQuery(GL_ANY_SAMPLES_PASSED);
    glDepthMask(GL_TRUE);
    return query;
}

bool GlImageTarget::queryAvailable(const OcclusionQuery& query) {
    const GlQuery& q = queries_.payload(query);
    if (q.trivial) return true;
    GLuint available = GL_FALSE;
    glGetQueryObjectuiv(q.name, GL_QUERY_RESULT_AVAILABLE, &available);
    return available != GL_FALSE;
}

bool GlImageTarget::queryResult(const OcclusionQuery& query) {
    const GlQuery q = queries_.payload(query);
    ++counts_.read;
    GLuint passed = GL_TRUE;
    if (!q.trivial) {
        GLuint available = GL_FALSE;
        glGetQueryObjectuiv(q.name, GL_QUERY_RESULT_AVAILABLE, &available);
        if (!available) ++counts_.stalled;
        glGetQueryObjectuiv(q.name, GL_QUERY_RESULT, &passed);
    }
    queries_.release(query);
    return passed != GL_FALSE;
}

}  // namespace gridcull
