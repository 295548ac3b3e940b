// How the scene view looks at the scene.
#pragma once

namespace gridcull {

enum class ViewMode {
    Overview,       // 3D: orbit around the world (right-drag, wheel); 2D: top-down map
    Fly,            // 3D: free observer camera (WASD, right-drag to look)
    CullingCamera,  // 3D: look through the culling camera
    Cameras,        // 3D: the orbit view and the culling camera's, side by side
};

}  // namespace gridcull
