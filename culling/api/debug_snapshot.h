// What a culler shows of its internal state to the window and to tests: the
// family's own snapshot struct (its matrices, traversal, cells, tests, ...),
// captured only while Culler::setDebugCapture(true).
//
// Shared code holds it as `const DebugSnapshot*` and never looks inside; the
// family's own code gets its type back with as<T>(), a checked cast by the
// snapshot's kind (no RTTI): each snapshot type declares
//   static const DebugSnapshotKind kKind;   // defined once, in the family's .cpp
// and passes it to this base.
#pragma once

namespace gridcull {

struct DebugSnapshotKind {
    const char* family;  // the registry id of the family that fills it
};

class DebugSnapshot {
public:
    explicit DebugSnapshot(const DebugSnapshotKind& kind) : kind_(&kind) {}
    virtual ~DebugSnapshot() = default;
    DebugSnapshot(const DebugSnapshot&) = default;
    DebugSnapshot& operator=(const DebugSnapshot&) = default;

    const DebugSnapshotKind& kind() const { return *kind_; }
    // This snapshot as a T when it is one, else nullptr.
    template <class T>
    const T* as() const {
        return kind_ == &T::kKind ? static_cast<const T*>(this) : nullptr;
    }

private:
    const DebugSnapshotKind* kind_;
};

}  // namespace gridcull
