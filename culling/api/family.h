// What an algorithm family gives the registry (culling/registry/registry.h): its
// algorithms with the dimensions each runs on, its knobs, and how to make a
// culler. One FamilyEntry per family, made by a function in the family's own
// folder (culling/<family>/<family>_family.h); the registry lists those
// functions and nothing else of the family. The family's window side
// (panel, overlay, view flags) is its entry in the ui registry, under the same id.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "culling/api/culler.h"
#include "culling/api/image_target.h"
#include "culling/api/knobs.h"

namespace gridcull {

// Which scenes an algorithm runs on, as a mask.
enum DimensionMask : int { kRuns2d = 1, kRuns3d = 2, kRunsBoth = kRuns2d | kRuns3d };

struct AlgorithmEntry {
    std::string name;  // as --algo takes it, e.g. "vfc"
    int dimensions = kRunsBoth;
    std::string summary;  // one line for help and the window
    // Frames in a row an object the oracle sees may be missing from the PVS by
    // design (Sudarsky & Gotsman's implicit update: 1); 0 for a conservative
    // algorithm. Tests hold the algorithm to it: a miss longer than this is a
    // false cull.
    int late_frames = 0;
};

// Everything a family's factory is given to make one culler.
struct CullerRequest {
    std::string algorithm;  // one of the family's AlgorithmEntry names
    std::string name;       // what the culler's name() reports (the algorithm, or e.g. NAME-gl)
    const KnobValues* knobs = nullptr;  // every knob's value; the family reads its own
    // The oracle's image side in pixels: an image-space family's default, so that
    // its false culls compare like with like.
    int reference_resolution = 0;
    // Where to draw, for a family with draws_image; null: the software rasterizer.
    std::unique_ptr<ImageTarget> target;
};

struct FamilyEntry {
    std::string id;     // e.g. "baseline"; the ui registry's key for its panel and overlay
    std::string title;  // e.g. "Baselines": how help and the window name the family
    std::vector<AlgorithmEntry> algorithms;
    std::vector<Knob> knobs;   // its options (its KnobTable's knobs())
    bool draws_image = false;  // its cullers take a CullerRequest::target
    // The reference every culler is checked against (the exact oracle): its first
    // algorithm runs beside the selected one, and its knobs apply to every run.
    bool reference = false;
    // Makes the culler of request.algorithm. Never fails for its own algorithms.
    std::function<std::unique_ptr<Culler>(CullerRequest& request)> make;
};

}  // namespace gridcull
