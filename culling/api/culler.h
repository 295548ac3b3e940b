// The one interface every culling algorithm implements. A culler keeps its
// state between frames (temporal coherence is the point of most of them), so
// frames must be given in order; call reset() when the scene changes or time
// jumps backwards. Cullers are made by name through the registry
// (culling/registry/registry.h), which also says which dimensions each runs on.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "culling/api/counters.h"
#include "culling/api/debug_snapshot.h"
#include "culling/scene/camera.h"
#include "culling/scene/scene.h"

namespace gridcull {

struct FrameResult {
    std::vector<int> pvs;  // potentially visible object ids, sorted ascending
    CullStats stats;
    // The exact oracle's "sub-sample" objects (exact_oracle.h), ids ascending,
    // none in pvs: those its finer rays saw between pixel centres (visible, but
    // on no pixel of an image at its resolution), and those they could not
    // decide. Empty for every other culler.
    std::vector<int> sub_sample_visible;
    std::vector<int> sub_sample_undecided;
};

class Culler {
public:
    virtual ~Culler() = default;
    // The --algo name, e.g. "vfc".
    virtual const char* name() const = 0;
    // Forget every frame seen so far and size buffers for `scene`.
    virtual void reset(const Scene& scene) = 0;
    // Computes the PVS at time t seen by `camera`. `out.pvs` is cleared and refilled
    // (its capacity is reused, so a steady state allocates nothing); out.stats is
    // reset, then filled with this algorithm's counters. cull_ms is set by timedCull.
    virtual void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) = 0;

    // Debug capture: while on, each cull() also fills the family's snapshot of
    // its internal state, which costs time and memory; off by default.
    virtual void setDebugCapture(bool on) { (void)on; }
    // The last frame's snapshot while capture is on and a frame was culled since;
    // nullptr otherwise (and always for a culler with nothing to show). Valid
    // until the next cull() or reset().
    virtual const DebugSnapshot* debugSnapshot() const { return nullptr; }

    // A copy of everything this culler keeps between frames, which continues from
    // the next frame exactly as this one would (the debugger's checkpoints, so a
    // seek backwards replays a few frames rather than all of them). The copy's
    // debug capture is as this one's, its snapshot empty until its next cull().
    // Null for a culler whose state cannot be copied (one that holds GPU
    // objects); callers then replay from frame 0.
    virtual std::unique_ptr<Culler> clone() const { return nullptr; }
};

// Runs culler.cull and sets out.stats.cull_ms from a steady clock.
void timedCull(Culler& culler, const Scene& scene, const Camera& camera, double t,
               FrameResult& out);

}  // namespace gridcull
