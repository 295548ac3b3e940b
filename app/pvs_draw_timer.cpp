#include "app/pvs_draw_timer.h"

#include "app/gl_api.h"
#include "app/gl_context.h"
#include "culling/raster/id_depth_buffer.h"

namespace gridcull {

bool PvsDrawTimer::init(const Scene& scene, int long_side, std::string& error) {
    if (!ensureHiddenGlContext(error)) {
        error = "drawing needs an OpenGL context: " + error;
        return false;
    }
    int width = 0, height = 0;
    imageSizeForAspect(long_side, scene.dimensions == 2 ? 1.0 : scene.camera.aspect, width,
                       height);
    if (!target_.create(width, height, error) || !renderer_.init(error)) return false;
    renderer_.setScene(scene);
    view_camera_.frameScene(scene);
    states_.assign(scene.objects.size(), ObjectState::Culled);
    return true;
}

std::string PvsDrawTimer::rendererName() const {
    const GLubyte* name = glGetString(GL_RENDERER);
    return name ? reinterpret_cast<const char*>(name) : "unknown";
}

double PvsDrawTimer::draw(const Scene& scene, const Camera& camera, double t,
                          const std::vector<int>& pvs) {
    std::fill(states_.begin(), states_.end(), ObjectState::Culled);
    for (int id : pvs) {
        const int index = scene.indexOf(id);
        if (index >= 0) states_[size_t(index)] = ObjectState::Visible;
    }
    SceneDrawInput input;
    input.scene = &scene;
    input.t = t;
    input.states = &states_;
    input.culling_camera = camera;
    input.show_culling_camera = false;
    input.pvs_only = true;
    const double aspect = double(target_.width()) / double(target_.height());
    input.view = view_camera_.matrices(
        scene.dimensions == 2 ? ViewMode::Overview : ViewMode::CullingCamera, camera, aspect);
    input.viewport = {0, 0, target_.width(), target_.height()};
    input.framebuffer_height = target_.height();
    target_.bind();
    return renderer_.draw(input);
}

}  // namespace gridcull
