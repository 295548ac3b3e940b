// The algorithms the executable offers: every culler of culling/ (cullerNames)
// plus those only the app can make because they need OpenGL: the lazy occlusion
// grids drawing with OpenGL and reading the depth buffer back per pixel-level
// query (app/gl_image_target.h), named like their software twins with "-gl".
// The first -gl culler made opens a hidden GLFW window for its context (so it
// needs an X display: run bench under xvfb-run on a headless machine), which
// lives until the program ends. Meant for `bench`; the window does not offer them.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "culling/api/culler.h"

namespace gridcull {

std::vector<std::string> appCullerNames();
// makeCuller, and the -gl cullers. nullptr with `error` set when it cannot.
std::unique_ptr<Culler> makeAppCuller(std::string_view name, const CullerOptions& options,
                                      std::string& error);

}  // namespace gridcull
