// Object motion (scene-format.md, "Motion"): linear motion reflected at the
// world bounds, keyframes interpolated and held, seeded random walks that keep
// their speed bound and come out the same on every load.
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include "culling/io/scene_loader.h"
#include "culling/scene/random_walk.h"

namespace gridcull {
namespace {

// Finite differences over this step may show a speed above max_speed only by
// rounding; positions are O(100), so 1e-9 relative is far above double error.
constexpr double kStep = 1e-3;
constexpr double kSpeedSlack = 1e-6;
// Bounds may leave the world only by rounding in the triangle wave.
constexpr double kInsideSlack = 1e-9;

Scene load(const std::string& objects, uint64_t seed = 1, int frames = 250) {
    const std::string text =
        R"({"format": "gridcull-scene/1", "dimensions": 3,
            "world": {"min": [0, 0, 0], "max": [100, 60, 100]},
            "time": {"frames": )" +
        std::to_string(frames) + R"(, "dt": 0.04}, "seed": )" + std::to_string(seed) +
        R"(, "camera": {"path": [{"t": 0, "position": [1, 1, 1], "target": [5, 5, 5]}]},
            "objects": [)" +
        objects + "]}";
    SceneLoadResult r = loadSceneText(text, "motion.json", "");
    EXPECT_TRUE(r.errors.empty()) << (r.errors.empty() ? "" : r.errors[0]);
    return r.scene ? *r.scene : Scene{};
}

bool inside(const Aabb& box, const Aabb& world) {
    for (int axis = 0; axis < 3; ++axis)
        if (box.min[axis] < world.min[axis] - kInsideSlack ||
            box.max[axis] > world.max[axis] + kInsideSlack)
            return false;
    return true;
}

TEST(SceneMotion, StaticNeverMoves) {
    const Scene s = load(R"({"shape": "box", "min": [1, 2, 3], "max": [4, 5, 6]})");
    const SceneObject& o = s.objects[0];
    EXPECT_EQ(s.displacementAt(o, 123.0), glm::dvec3(0.0));
    EXPECT_EQ(s.positionAt(o.id, 7.0), glm::dvec3(2.5, 3.5, 4.5));
    EXPECT_EQ(s.boundsAt(o, 7.0).min, glm::dvec3(1, 2, 3));
}

TEST(SceneMotion, LinearMatchesVelocityAwayFromWalls) {
    const Scene s = load(R"({"shape": "sphere", "center": [50, 30, 50], "radius": 2,
                             "motion": {"type": "linear", "velocity": [4, -2, 1]}})");
    const SceneObject& o = s.objects[0];
    // The first wall it meets is x = 100, after (100 - 52) / 4 = 12 s.
    for (double t = 0.0; t < 11.95; t += 0.1) {
        const glm::dvec3 expected = o.anchor + glm::dvec3(4, -2, 1) * t;
        const glm::dvec3 got = s.positionAt(o.id, t);
        EXPECT_NEAR(glm::length(got - expected), 0.0, 1e-9) << t;
    }
    EXPECT_DOUBLE_EQ(o.motion.max_speed, std::sqrt(21.0));
}

TEST(SceneMotion, LinearReflectsAndStaysInsideTheWorld) {
    const Scene s = load(R"({"shape": "sphere", "center": [50, 30, 50], "radius": 2,
                             "motion": {"type": "linear", "velocity": [23, -17, 11]}})");
    const SceneObject& o = s.objects[0];
    const Aabb& world = s.grid.world;
    double lowest_x = 1e9, highest_x = -1e9, lowest_y = 1e9;
    glm::dvec3 previous = s.positionAt(o.id, 0.0);
    for (double t = kStep; t < 60.0; t += kStep) {
        const Aabb box = s.boundsAt(o, t);
        ASSERT_TRUE(inside(box, world)) << t;
        lowest_x = std::min(lowest_x, box.min.x);
        highest_x = std::max(highest_x, box.max.x);
        lowest_y = std::min(lowest_y, box.min.y);
        const glm::dvec3 p = s.positionAt(o.id, t);
        // Reflection flips components, so the speed never grows.
        EXPECT_LE(glm::length(p - previous) / kStep, o.motion.max_speed * (1 + kSpeedSlack)) << t;
        previous = p;
    }
    // It does bounce off the walls rather than stop short of them.
    EXPECT_NEAR(lowest_x, 0.0, 0.05);
    EXPECT_NEAR(highest_x, 100.0, 0.05);
    EXPECT_NEAR(lowest_y, 0.0, 0.05);
}

TEST(SceneMotion, LinearHoldsAxesWhereTheObjectCannotMoveInside) {
    // Larger than the world in y, and outside it in x at t = 0: only z moves.
    const Scene s = load(R"({"shape": "box", "min": [-20, -5, 40], "max": [-10, 70, 42],
                             "motion": {"type": "linear", "velocity": [5, 5, 5]}})");
    const SceneObject& o = s.objects[0];
    for (double t = 0.0; t < 30.0; t += 0.5) {
        const glm::dvec3 d = s.displacementAt(o, t);
        EXPECT_EQ(d.x, 0.0);
        EXPECT_EQ(d.y, 0.0);
        EXPECT_GE(s.boundsAt(o, t).min.z, -kInsideSlack);
        EXPECT_LE(s.boundsAt(o, t).max.z, 100.0 + kInsideSlack);
    }
    EXPECT_NEAR(s.displacementAt(o, 2.0).z, 10.0, 1e-12);
}

TEST(SceneMotion, KeyframesInterpolateAndHold) {
    const Scene s = load(R"({"shape": "sphere", "center": [0, 0, 0], "radius": 1,
        "motion": {"type": "keyframes", "keys": [
            {"t": 1, "position": [10, 0, 0]}, {"t": 3, "position": [20, 0, 0]},
            {"t": 4, "position": [20, 10, 0]}]}})");
    const SceneObject& o = s.objects[0];
    auto at = [&](double t) { return s.positionAt(o.id, t); };
    EXPECT_EQ(at(-5.0), glm::dvec3(10, 0, 0));
    EXPECT_EQ(at(0.0), glm::dvec3(10, 0, 0));
    EXPECT_EQ(at(1.0), glm::dvec3(10, 0, 0));
    EXPECT_NEAR(glm::length(at(2.0) - glm::dvec3(15, 0, 0)), 0.0, 1e-12);
    EXPECT_EQ(at(3.0), glm::dvec3(20, 0, 0));
    EXPECT_NEAR(glm::length(at(3.5) - glm::dvec3(20, 5, 0)), 0.0, 1e-12);
    EXPECT_EQ(at(4.0), glm::dvec3(20, 10, 0));
    EXPECT_EQ(at(100.0), glm::dvec3(20, 10, 0));
    // Displacement is from where the shape stands at t = 0 (its anchor).
    EXPECT_EQ(s.displacementAt(o, 0.0), glm::dvec3(10, 0, 0));
    EXPECT_EQ(s.boundsAt(o, 4.0).min, glm::dvec3(19, 9, -1));
    EXPECT_DOUBLE_EQ(o.motion.max_speed, 10.0);
}

TEST(SceneMotion, RandomWalkKeepsItsSpeedBoundAndTheWorld) {
    const Scene s = load(R"(
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "random", "max_speed": 3}},
        {"shape": "sphere", "center": [2, 2, 2], "radius": 1.5,
         "motion": {"type": "random", "max_speed": 40}},
        {"shape": "box", "min": [10, 10, 10], "max": [20, 12, 30],
         "motion": {"type": "random", "max_speed": 7}})");
    for (const SceneObject& o : s.objects) {
        ASSERT_EQ(o.motion.kind, MotionKind::Random);
        ASSERT_FALSE(o.motion.segment_velocities.empty());
        const double span = o.motion.segment_seconds * double(o.motion.segment_velocities.size());
        EXPECT_GE(span, s.frames * s.dt);
        glm::dvec3 previous = s.positionAt(o.id, 0.0);
        EXPECT_EQ(previous, o.anchor);
        double fastest = 0.0, farthest = 0.0;
        for (double t = kStep; t < span + 1.0; t += kStep) {
            const glm::dvec3 p = s.positionAt(o.id, t);
            fastest = std::max(fastest, glm::length(p - previous) / kStep);
            farthest = std::max(farthest, glm::length(p - o.anchor));
            previous = p;
            ASSERT_TRUE(inside(s.boundsAt(o, t), s.grid.world)) << o.id << " " << t;
        }
        EXPECT_LE(fastest, o.motion.max_speed * (1 + kSpeedSlack)) << o.id;
        // The walk really moves at a good share of its bound.
        EXPECT_GT(fastest, 0.5 * o.motion.max_speed) << o.id;
        EXPECT_GT(farthest, 0.5) << o.id;
        // Held after the precomputed span.
        EXPECT_EQ(s.positionAt(o.id, span + 2.0), s.positionAt(o.id, span + 50.0));
    }
}

TEST(SceneMotion, RandomWalkIsDeterministicPerSeedAndObject) {
    const std::string objects = R"(
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "random", "max_speed": 3}},
        {"shape": "sphere", "center": [50, 30, 50], "radius": 1,
         "motion": {"type": "random", "max_speed": 3}})";
    const Scene a = load(objects, 42);
    const Scene b = load(objects, 42);
    const Scene c = load(objects, 43);
    bool seeds_differ = false, objects_differ = false;
    for (double t = 0.0; t < 10.0; t += 0.1) {
        for (int id = 0; id < 2; ++id) EXPECT_EQ(a.positionAt(id, t), b.positionAt(id, t));
        seeds_differ = seeds_differ || a.positionAt(0, t) != c.positionAt(0, t);
        objects_differ = objects_differ || a.positionAt(0, t) != a.positionAt(1, t);
    }
    EXPECT_TRUE(seeds_differ);
    EXPECT_TRUE(objects_differ);
}

TEST(SceneMotion, RandomWalkWithoutPrefixSumsGivesTheSameDisplacement) {
    Scene s = load(R"({"shape": "sphere", "center": [50, 30, 50], "radius": 1,
                       "motion": {"type": "random", "max_speed": 5}})");
    SceneObject hand = s.objects[0];
    hand.motion.segment_offsets.clear();  // as a hand-built motion might come
    for (double t = 0.0; t < 12.0; t += 0.13) {
        const glm::dvec3 a = s.displacementAt(s.objects[0], t);
        const glm::dvec3 b = s.displacementAt(hand, t);
        EXPECT_NEAR(glm::length(a - b), 0.0, 1e-9) << t;
    }
}

TEST(SceneMotion, BuildRandomWalkRespectsTheBoundIn2D) {
    Motion m;
    m.kind = MotionKind::Random;
    m.max_speed = 2.0;
    buildRandomWalk(m, 2, 99, 7, 50, 0.25);
    ASSERT_EQ(m.segment_velocities.size(), 50u);
    ASSERT_EQ(m.segment_offsets.size(), 51u);
    EXPECT_DOUBLE_EQ(m.segment_seconds, 0.25);
    for (size_t i = 0; i < 50; ++i) {
        EXPECT_LE(glm::length(m.segment_velocities[i]), 2.0 * (1 + 1e-12));
        EXPECT_EQ(m.segment_velocities[i].z, 0.0);
        const glm::dvec3 step = m.segment_offsets[i + 1] - m.segment_offsets[i];
        EXPECT_NEAR(glm::length(step - m.segment_velocities[i] * 0.25), 0.0, 1e-12);
    }
}

TEST(SceneMotion, ManyRandomObjectsShareTheSegmentBudget) {
    // 2000 random spheres over a long run: each walk gets fewer, longer
    // segments so that all of them stay within kMaxRandomSegments.
    const std::string text = R"({"format": "gridcull-scene/1", "dimensions": 2,
        "world": {"min": [0, 0], "max": [100, 100]}, "time": {"frames": 100000, "dt": 0.04},
        "camera": {"path": [{"t": 0, "position": [1, 1], "target": [5, 5]}]},
        "generators": [{"type": "sphere_cluster", "count": 2000, "radius": [0.1, 0.2],
                        "dynamic_fraction": 1, "max_speed": 1, "motion": "random"}]})";
    const SceneLoadResult r = loadSceneText(text, "many.json", "");
    ASSERT_TRUE(r.scene.has_value());
    int64_t segments = 0;
    for (const SceneObject& o : r.scene->objects) {
        segments += int64_t(o.motion.segment_velocities.size());
        EXPECT_GE(o.motion.segment_seconds * double(o.motion.segment_velocities.size()),
                  r.scene->frames * r.scene->dt * (1 - 1e-12));
    }
    EXPECT_LE(segments, kMaxRandomSegments);
}

}  // namespace
}  // namespace gridcull
