// The family registry: the one table of every algorithm family (the baselines,
// the oracle, and each occlusion-culling family). The command
// line's --algo list and help, bench's NAME:FLAG=VALUE entries, the window's
// culler list and knobs and docs/LIMITS.md's knob table all come from it, so a
// family is added by one line in registry.cpp (and one in the ui registry for
// its panel and overlay): docs/ARCHITECTURE.md, "Adding a family".
#pragma once
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "culling/api/family.h"

namespace gridcull {

// Every family, in the order help and the window list them. References and
// pointers into it (entries, algorithms, knobs) stay valid until the next
// registerFamily or unregisterFamily, which tests call before anything else.
const std::vector<FamilyEntry>& families();

// Adds a family after the built-in ones (tests add a test-only family this
// way). False with `error` when its id, an algorithm name or a knob flag is
// already taken, or it has no algorithm or no factory.
bool registerFamily(FamilyEntry entry, std::string& error);
// Removes a family added by registerFamily (the built-in ones stay).
void unregisterFamily(const std::string& id);

const FamilyEntry* findFamily(std::string_view id);
// The family of algorithm `name` and its entry there, or nullptr.
const FamilyEntry* familyOfAlgorithm(std::string_view name,
                                     const AlgorithmEntry** algorithm = nullptr);

// Every algorithm name, in registry order; with `dimensions` 2 or 3 only those
// that run on scenes of that dimension.
std::vector<std::string> algorithmNames(int dimensions = 0);
// "all, vfc, exact, ...", for messages.
std::string algorithmList(int dimensions = 0);

// Whether algorithm `name` runs on `scene`; else `why` names the dimension, e.g.
// "NAME runs on 3D scenes only, and this scene is 2D; algorithms for it: ...".
bool algorithmFits(std::string_view name, const Scene& scene, std::string& why);

// Every knob of every family, in registry order, and the one with `flag`.
std::vector<const Knob*> allKnobs();
const Knob* findKnob(std::string_view flag);
// The family that owns the knob `flag`, or nullptr.
const FamilyEntry* familyOfKnob(std::string_view flag);

// The reference algorithm (the exact oracle, "exact"): the first algorithm of
// the family marked `reference`.
const std::string& referenceAlgorithm();
// The algorithm the window (`gridcull` alone, `view`) and `shot` start with,
// and the window's fallback when a newly opened scene does not fit the
// selected one; and the last resort when the scene does not fit that either
// (an algorithm that runs on every scene). Both are registered algorithms.
const std::string& defaultAlgorithm();
const std::string& lastResortAlgorithm();

// The oracle's image side for these values: what image-space families match by
// default (CullerRequest::reference_resolution).
int referenceResolution(const KnobValues& knobs);

// Makes the culler named `name` with `knobs`, or returns nullptr and sets
// `error` ("unknown algorithm 'x', expected one of: ..."). `target`, for a
// family that draws an image, replaces the software rasterizer; `display_name`
// (non-empty) replaces the culler's name(), e.g. "NAME-gl".
std::unique_ptr<Culler> makeCuller(std::string_view name, const KnobValues& knobs,
                                   std::string& error,
                                   std::unique_ptr<ImageTarget> target = nullptr,
                                   const std::string& display_name = "");

}  // namespace gridcull
