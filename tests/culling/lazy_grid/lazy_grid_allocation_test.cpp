// "Hot per-frame paths do not allocate": once a lazy grid culler has seen a
// scene's first frames, cull() allocates nothing (snapshots off), moving objects,
// BVH refits and rebuilds included. Counted by replacing the global operator new
// of this test binary; the counter runs only inside the measured frames.
#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "culling/api/culler.h"
#include "tests/common/oracle_test_scenes.h"
#include "tests/culling/lazy_grid/lazy_grid_random_scene.h"

// GCC 12 flags free() of operator new's memory once it inlines the pair; here
// both sides are ours and use malloc / free.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    return ::operator new(size);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}

namespace gridcull {
namespace {

TEST(LazyGridAllocation, TheCounterSeesAnAllocation) {
    g_allocations = 0;
    g_counting = true;
    auto* v = new std::vector<int>(10);
    g_counting = false;
    delete v;
    EXPECT_EQ(g_allocations, 2);  // the vector and its buffer
}

TEST(LazyGridAllocation, SteadyFramesAllocateNothing) {
    for (uint64_t seed : {3u, 8u, 21u, 34u}) {
        const Scene scene = test::lazyGridRandomScene(seed);
        KnobValues options;
        options.set("oracle-res", 320);
        for (const char* name : {"lazy-grid", "lazy-grid-z", "busy-grid", "busy-grid-tight"}) {
            auto culler = test::makeOrDie(name, options);
            culler->reset(scene);
            FrameResult result;
            result.pvs.reserve(scene.objects.size());
            for (int frame = 0; frame < 3; ++frame)
                culler->cull(scene, cameraAt(scene, scene.timeOfFrame(frame)),
                             scene.timeOfFrame(frame), result);
            long allocations = 0;
            for (int frame = 3; frame < scene.frames; ++frame) {
                const double t = scene.timeOfFrame(frame);
                const Camera camera = cameraAt(scene, t);
                g_allocations = 0;
                g_counting = true;
                culler->cull(scene, camera, t, result);
                g_counting = false;
                allocations += g_allocations;
            }
            EXPECT_EQ(allocations, 0) << name << " seed " << seed;
        }
    }
}

}  // namespace
}  // namespace gridcull
