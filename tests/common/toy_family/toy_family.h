// A trivial test-only algorithm family, "toy", added the way docs/ARCHITECTURE.md
// ("Adding a family") says a real one is, but at run time by the tests instead
// of by a line in the registries: `toy-nearest` keeps the `--toy-count` objects
// whose anchors are nearest the culling camera (not conservative, and not meant
// to be). It has everything a family has: an options struct with its knob
// table, a culler, a debug snapshot, a registry entry, and a window side whose
// panel and overlay use every primitive of the debug-draw interface (voxels,
// cells, rectangles, dashes, hatches, lines, polygons, text labels). The
// screenshot tests draw it through `gridcull-toy` (toy_main.cpp), the gridcull
// executable with this family registered.
#pragma once
#include <string>

namespace gridcull::test {

// Adds the toy family to the culling registry and its view to the ui registry.
// False with `error` when either refuses it. Idempotent.
bool registerToyFamily(std::string& error);
// Removes both again.
void unregisterToyFamily();

}  // namespace gridcull::test
