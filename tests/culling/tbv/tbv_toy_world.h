// A toy culler around TbvManager for the manager's tests: a 2D world whose
// visible part is the half-plane x >= 0 (everything at x < 0 is behind a wall),
// objects that are discs moving along functions of time, and a "spatial
// structure" T that is one entry per object: nothing, the object's disc as it
// was when last written (upd_vis), or its TBV's bounding box. The traversal
// (step 3) looks at every entry of T in id order, which no real culler would
// do; the tests measure the manager, not the toy's T.
//
// Step 3, as the paper's: an entry that holds the object (possibly written at
// an older configuration, TBVi) is met when that written disc is in view; the
// object is then tested at its current configuration and, if in view, drawn
// and observed. A TBV met in view is revealed, the object written in at its
// current configuration and tested at once (the changes to T are not
// postponed, so a revealed object shows up in the same frame).
#pragma once
#include <functional>
#include <utility>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/tbv/tbv_manager.h"

namespace gridcull::test {

struct ToyObject {
    std::function<glm::dvec3(double)> position;  // its centre at time t
    double radius = 0.5;
    double max_speed = 1.0;  // declared: what its TBVs are made from
};

inline TbvBox toyDisc(const glm::dvec3& centre, double radius) {
    return {centre - glm::dvec3(radius, radius, 0.0), centre + glm::dvec3(radius, radius, 0.0)};
}
inline bool toyInView(const TbvBox& box) {
    return box.max.x >= 0.0;
}

struct ToyFrame {
    std::vector<int> shown;                              // observed, in id order
    std::vector<std::pair<int, TbvDropReason>> dropped;  // step 1's drops
    std::vector<int> revealed;                           // step 3's reveals
    TbvFrameCounters counters;

    void reserve(size_t objects) {
        shown.reserve(objects);
        dropped.reserve(objects);
        revealed.reserve(objects);
    }
};

class ToyTbvCuller {
public:
    ToyTbvCuller(std::vector<ToyObject> objects, const TbvManagerOptions& options)
        : objects_(std::move(objects)) {
        manager_.reset(objects_.size(), options);
        entries_.assign(objects_.size(), Entry{});
        for (size_t i = 0; i < objects_.size(); ++i) manager_.addDynamic(int(i));
    }

    // The objects' controller checks its objects against their TBVs (before
    // the frame, at the frame's time) and reports those outside.
    bool report_violations = false;

    ToyFrame frame(double t) {
        ToyFrame out;
        frame(t, out);
        return out;
    }

    // The same into `out`, whose lists are cleared and reused: with them
    // reserved for every object, a frame of the toy allocates nothing itself.
    void frame(double t, ToyFrame& out) {
        out.shown.clear();
        out.dropped.clear();
        out.revealed.clear();
        if (report_violations) {
            for (size_t i = 0; i < objects_.size(); ++i)
                if (manager_.violates(int(i), objects_[i].position(t), objects_[i].radius))
                    manager_.reportViolation(int(i));
        }
        // Step 1.
        manager_.beginFrame(t, [&](int id, TbvDropReason why) {
            entries_[size_t(id)] = Entry{};  // the TBV leaves T
            out.dropped.push_back({id, why});
        });
        // Step 2.
        for (const int id : manager_.objectsToUpdate()) write(id, t);
        // Step 3.
        for (size_t i = 0; i < objects_.size(); ++i) {
            const int id = int(i);
            Entry& e = entries_[i];
            if (e.kind == Kind::Tbv && toyInView(e.box)) {
                manager_.reveal(id);
                out.revealed.push_back(id);
                write(id, t);
            }
            if (e.kind == Kind::Object && toyInView(e.box) && toyInView(discAt(id, t))) {
                manager_.observe(id);
                out.shown.push_back(id);
            }
        }
        // Step 4.
        manager_.endFrame([&](int id, double& validity) {
            const ToyObject& o = objects_[size_t(id)];
            const TbvShape s = sphereTbv(2, o.position(t), o.radius, o.max_speed, validity);
            entries_[size_t(id)] = Entry{Kind::Tbv, tbvBounds(s)};
            return s;
        });
        out.counters = manager_.frameCounters();
    }

    TbvManager& manager() { return manager_; }
    const std::vector<ToyObject>& objects() const { return objects_; }

private:
    enum class Kind { None, Object, Tbv };
    struct Entry {
        Kind kind = Kind::None;
        TbvBox box;
    };
    TbvBox discAt(int id, double t) const {
        return toyDisc(objects_[size_t(id)].position(t), objects_[size_t(id)].radius);
    }
    void write(int id, double t) {
        manager_.updVis(id);
        entries_[size_t(id)] = Entry{Kind::Object, discAt(id, t)};
    }

    std::vector<ToyObject> objects_;
    std::vector<Entry> entries_;
    TbvManager manager_;
};

// An object standing still at (x, 0).
inline ToyObject toyStill(double x, double radius = 0.5, double max_speed = 1.0) {
    return {[x](double) { return glm::dvec3(x, 0.0, 0.0); }, radius, max_speed};
}
// An object moving along x: x0 + speed * t.
inline ToyObject toyMoving(double x0, double speed, double radius = 0.5, double max_speed = 1.0) {
    return {[x0, speed](double t) { return glm::dvec3(x0 + speed * t, 0.0, 0.0); }, radius,
            max_speed};
}

}  // namespace gridcull::test
