// Monotonicity on seeded random scenes. With S a scene, O an
// extra occluder and R one of S's objects, a PVS function P is monotone when
//   adding:   P(S + O) - {O} is a subset of P(S)  (an occluder never reveals), and
//   removing: P(S - R) contains P(S) - {R}        (removing one never hides).
// The oracle must be monotone exactly: each pixel (ray) reports the nearest
// object along it, ties broken by a fixed order of the objects (nearest
// possible depth, then index), which adding or removing an object does not
// change for the others; so the winner of a pixel either stays or becomes O.
// Each culler (whose heuristics need not be monotone) is measured, not held to
// it: one line per algorithm reports how many of the trials were monotone.
//   [monotonic] ALGO | adding: M of N monotone | removing: M of N monotone
// Seeds: 0..kSeeds-1, or GRIDCULL_SEED alone; a failing seed prints the command
// that replays it.
#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/culling/registry/extremes_harness.h"
#include "tests/culling/registry/extremes_scenes.h"

namespace gridcull {
namespace {

constexpr int kSeeds = 200;
constexpr int kOccluderId = 100000;

struct Trial {
    Scene scene, with_occluder, without_one;
    int removed_id = -1;
    Camera camera;
    double t = 0.0;
};

Trial makeTrial(uint64_t seed) {
    SeededRandom rng(seed, 9);
    const int dims = seed % 2 == 0 ? 2 : 3;
    Trial trial;
    Scene& scene = trial.scene;
    scene = dims == 3 ? test::scene3d() : test::scene2d();
    test::addRandomObjects(scene, rng, 30 + int(rng.below(60)));
    if (dims == 3) {
        // A few meshes, closed and open.
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3 p{rng.uniform(0, 100), rng.uniform(0, 100), rng.uniform(0, 100)};
            test::addMesh(scene, int(scene.objects.size()), p,
                          k == 0   ? test::cubeMesh(4)
                          : k == 1 ? test::tetrahedronMesh(5)
                                   : test::quadMesh(6));
        }
    }
    auto point = [&](double lo, double hi) {
        return glm::dvec3{rng.uniform(lo, hi), rng.uniform(lo, hi),
                          dims == 3 ? rng.uniform(lo, hi) : 0.0};
    };
    const glm::dvec3 eye = point(0, 100);
    const glm::dvec3 dir = randomDirection(rng, dims);
    const double fov = dims == 3 ? rng.uniform(30, 120) : rng.uniform(30, 360);
    trial.camera = test::makeCamera(dims, eye, eye + dir * 10.0, fov, rng.uniform(0.7, 2.0), 0.1,
                                    rng.uniform(60, 300));
    trial.t = rng.uniform(0, 2);
    test::adoptCamera(scene, trial.camera);
    scene.finalize();

    // The occluder: in front of the camera, near enough to hide something.
    trial.with_occluder = scene;
    const glm::dvec3 at = eye + dir * rng.uniform(3, 25) + point(-3, 3);
    const double size = rng.uniform(2, 15);
    if (rng.uniform() < 0.5) {
        test::addSphere(trial.with_occluder, kOccluderId, at, size);
    } else {
        const glm::dvec3 half = dims == 3 ? glm::dvec3(size, size, rng.uniform(0.05, 2))
                                          : glm::dvec3(size, rng.uniform(0.05, 2), 0);
        test::addBox(trial.with_occluder, kOccluderId, at - half, at + half);
    }
    trial.with_occluder.finalize();

    trial.without_one = scene;
    const size_t removed = rng.below(scene.objects.size());
    trial.removed_id = scene.objects[removed].id;
    trial.without_one.objects.erase(trial.without_one.objects.begin() + long(removed));
    trial.without_one.finalize();
    return trial;
}

std::vector<int> pvsOf(Culler& culler, const Scene& scene, const Camera& camera, double t) {
    culler.reset(scene);
    FrameResult out;
    culler.cull(scene, camera, t, out);
    return out.pvs;
}

std::vector<int> without(std::vector<int> ids, int id) {
    ids.erase(std::remove(ids.begin(), ids.end(), id), ids.end());
    return ids;
}

struct Tally {
    int add_monotone = 0, add_trials = 0;
    int remove_monotone = 0, remove_trials = 0;
    int skipped = 0;
};

TEST(ExtremesMonotonic, OracleIsMonotoneAndCullersAreMeasured) {
    KnobValues knobs;
    knobs.set("oracle-res", 320);
    knobs.set("oracle-rays", 8192);
    std::map<std::string, Tally> tallies;
    int hiding_trials = 0;  // trials where the occluder hid something: the test has teeth
    for (const uint64_t seed : test::seedsToRun(0, kSeeds)) {
        test::withSeed(seed, [&] {
            const Trial trial = makeTrial(seed);
            for (const std::string& name : algorithmNames()) {
                std::string error;
                Tally& tally = tallies[name];
                if (!algorithmFits(name, trial.scene, error)) {
                    ++tally.skipped;
                    continue;
                }
                std::unique_ptr<Culler> culler = makeCuller(name, knobs, error);
                ASSERT_TRUE(culler) << error;
                const std::vector<int> base = pvsOf(*culler, trial.scene, trial.camera, trial.t);
                const std::vector<int> added = without(
                    pvsOf(*culler, trial.with_occluder, trial.camera, trial.t), kOccluderId);
                const std::vector<int> removed =
                    pvsOf(*culler, trial.without_one, trial.camera, trial.t);
                const std::vector<int> base_minus = without(base, trial.removed_id);
                const bool add_ok = test::isSubset(added, base);
                const bool remove_ok = test::isSubset(base_minus, removed);
                tally.add_trials++;
                tally.remove_trials++;
                tally.add_monotone += add_ok ? 1 : 0;
                tally.remove_monotone += remove_ok ? 1 : 0;
                if (name == "exact") {
                    hiding_trials += added.size() < base.size() ? 1 : 0;
                    EXPECT_TRUE(add_ok) << "adding an occluder revealed ids: before "
                                        << test::idList(base) << ", after " << test::idList(added);
                    EXPECT_TRUE(remove_ok)
                        << "removing id " << trial.removed_id << " hid ids: before "
                        << test::idList(base_minus) << ", after " << test::idList(removed);
                }
            }
        });
    }
    for (const std::string& name : algorithmNames()) {
        const Tally& t = tallies[name];
        std::printf("[monotonic] %s | adding: %d of %d monotone | removing: %d of %d monotone",
                    name.c_str(), t.add_monotone, t.add_trials, t.remove_monotone, t.remove_trials);
        if (t.skipped > 0)
            std::printf(" | skipped on %d scenes (not offered for its dimension)", t.skipped);
        std::printf("\n");
    }
    std::printf("[monotonic] the added occluder hid something from the oracle in %d trials\n",
                hiding_trials);
    if (!test::singleSeedRun()) {
        // Most occluders in front of the camera hide something; if none did, the
        // scenes would prove nothing.
        EXPECT_GT(hiding_trials, kSeeds / 4);
    }
}

}  // namespace
}  // namespace gridcull
