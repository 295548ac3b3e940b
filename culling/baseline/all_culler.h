// The `all` baseline: no culling at all, every object of the scene is reported
// potentially visible (the plain z-buffer, "ZB" in the papers' tables).
// Cost: O(n) per frame, plus a sort when the scene's objects are not listed in
// ascending id order. Reports no counters besides cull_ms.
#pragma once
#include "culling/api/culler.h"

namespace gridcull {

class AllCuller final : public Culler {
public:
    const char* name() const override { return "all"; }
    void reset(const Scene& scene) override;
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override;
    std::unique_ptr<Culler> clone() const override { return std::make_unique<AllCuller>(*this); }
};

}  // namespace gridcull
