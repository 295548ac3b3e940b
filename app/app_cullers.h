// The algorithms the executable offers: every algorithm of the registry, plus,
// for each family that draws an image (FamilyEntry::draws_image), each of its
// algorithms drawing with OpenGL instead of the software rasterizer, named
// NAME-gl: the image is a GL framebuffer and each pixel query a read-back
// (app/gl_image_target.h), as a GPU implementation measures it. The first -gl
// culler made opens a hidden GLFW window for its context (so it needs an X
// display: run bench under xvfb-run on a headless machine), which lives until
// the program ends. Meant for `cull` and `bench`; the window does not offer them.
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/knobs.h"

namespace gridcull {

// The suffix of the OpenGL variants.
constexpr std::string_view kGlSuffix = "-gl";

// Every name --algo takes in `cull` and `bench`: the registry's, then the -gl ones.
std::vector<std::string> appAlgorithmNames();
// The registry name behind `name` ("NAME" for "NAME-gl"), or "" when
// `name` is neither a registry algorithm nor one of its -gl variants.
std::string registryAlgorithmOf(std::string_view name);
// makeCuller, and the -gl cullers. nullptr with `error` set when it cannot.
std::unique_ptr<Culler> makeAppCuller(std::string_view name, const KnobValues& knobs,
                                      std::string& error);

}  // namespace gridcull
