// The lazy occlusion grid's registry entry: `lazy-grid` (occlusion-buffer
// variant), `lazy-grid-z` (z-buffer variant), `busy-grid` (the paper's busy
// update) and `busy-grid-tight` (a stronger busy baseline), 3D scenes, with
// their knobs (culling/lazy_grid/lazy_grid_options.h). They draw an image, so
// the app may give them an OpenGL target.
#pragma once
#include "culling/api/family.h"

namespace gridcull {

FamilyEntry lazyGridFamily();

}  // namespace gridcull
