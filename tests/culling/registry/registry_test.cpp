// The family registry (culling/registry/registry.h): the algorithm names, the
// dimensions each runs on, the knobs and their owners, making cullers by name,
// and adding a family.
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "culling/baseline/vfc_culler.h"
#include "culling/registry/registry.h"
#include "tests/common/oracle_test_scenes.h"

namespace gridcull {
namespace {

TEST(Registry, MakesEveryListedCullerUnderItsName) {
    const std::vector<std::string> names = algorithmNames();
    EXPECT_EQ(names, (std::vector<std::string>{"all", "vfc", "exact", "rgvc", "lazy-grid",
                                               "lazy-grid-z", "busy-grid", "busy-grid-tight",
                                               "hzb-tbv", "hzb-tbvi", "hzb", "bsp-oq",
                                               "bsp-oq-simple", "bsp-vfc"}));
    for (const std::string& name : names) {
        std::string error;
        auto culler = makeCuller(name, KnobValues{}, error);
        ASSERT_TRUE(culler) << name << ": " << error;
        EXPECT_EQ(std::string(culler->name()), name);
        EXPECT_TRUE(error.empty());
    }
}

TEST(Registry, UnknownNameIsAnErrorThatListsTheKnownOnes) {
    std::string error;
    EXPECT_EQ(makeCuller("rgvcc", KnobValues{}, error), nullptr);
    EXPECT_NE(error.find("rgvcc"), std::string::npos) << error;
    for (const std::string& name : algorithmNames())
        EXPECT_NE(error.find(name), std::string::npos) << error;
    error.clear();
    EXPECT_EQ(makeCuller("", KnobValues{}, error), nullptr);
    EXPECT_FALSE(error.empty());
}

TEST(Registry, SaysWhichDimensionsEachAlgorithmRunsOn) {
    EXPECT_EQ(algorithmNames(2), (std::vector<std::string>{"all", "vfc", "exact", "rgvc"}));
    EXPECT_EQ(
        algorithmNames(3),
        (std::vector<std::string>{"all", "vfc", "exact", "rgvc", "lazy-grid", "lazy-grid-z",
                                  "busy-grid", "busy-grid-tight", "hzb-tbv", "hzb-tbvi", "hzb",
                                  "bsp-oq", "bsp-oq-simple", "bsp-vfc"}));
    std::string why;
    EXPECT_TRUE(algorithmFits("vfc", test::scene2d(), why));
    EXPECT_TRUE(algorithmFits("lazy-grid", test::scene3d(), why));
    EXPECT_FALSE(algorithmFits("lazy-grid", test::scene2d(), why));
    EXPECT_EQ(why,
              "lazy-grid runs on 3D scenes only, and this scene is 2D; algorithms for it: all, "
              "vfc, exact, rgvc");
    EXPECT_FALSE(algorithmFits("nope", test::scene2d(), why));
    EXPECT_NE(why.find("unknown algorithm 'nope'"), std::string::npos) << why;
}

TEST(Registry, KnobsAreUniqueAndNamedAfterTheirFamily) {
    std::set<std::string> flags;
    for (const Knob* knob : allKnobs()) {
        EXPECT_TRUE(flags.insert(knob->flag).second) << knob->flag;
        const FamilyEntry* family = familyOfKnob(knob->flag);
        ASSERT_TRUE(family) << knob->flag;
        EXPECT_EQ(findKnob(knob->flag), knob);
        // The prefix says whose knob it is: "lazy-" for "lazy-grid", "oracle-", "rgvc-".
        const std::string prefix = family->id.substr(0, family->id.find('-')) + "-";
        EXPECT_EQ(knob->flag.compare(0, prefix.size(), prefix), 0) << knob->flag;
        EXPECT_LE(knob->min, knob->max) << knob->flag;
        if (knob->automatic.empty()) {
            EXPECT_GE(knob->default_value, knob->min) << knob->flag;
            EXPECT_LE(knob->default_value, knob->max) << knob->flag;
        }
        EXPECT_FALSE(knob->help.empty()) << knob->flag;
    }
    EXPECT_EQ(findKnob("grid-res"), nullptr);
    EXPECT_EQ(findKnob("cell-size"), nullptr);
}

// What trade sweeps: every culler family's knob, over values it accepts, read
// by algorithms of its own family; the reference's knobs are never swept (they
// judge every setting).
TEST(Registry, EveryCullerKnobIsSweptOverValuesItAccepts) {
    for (const FamilyEntry& family : families()) {
        for (const Knob& knob : family.knobs) {
            if (family.reference) {
                EXPECT_TRUE(knob.sweep.empty()) << knob.flag;
                continue;
            }
            EXPECT_GE(knob.sweep.size(), 2u) << knob.flag;
            for (double v : knob.sweep) {
                EXPECT_GE(v, knob.min) << knob.flag;
                EXPECT_LE(v, knob.max) << knob.flag;
                if (knob.kind == KnobKind::Integer) EXPECT_EQ(v, std::round(v)) << knob.flag;
            }
            for (const std::string& reader : knob.read_by) {
                const FamilyEntry* owner = familyOfAlgorithm(reader);
                EXPECT_EQ(owner, &family) << knob.flag << " read by " << reader;
            }
        }
    }
}

// Every counter of the table is reported by some algorithm of the registry: the
// table holds no name ahead of its use.
TEST(Registry, EveryCounterIsReportedBySomeAlgorithm) {
    KnobValues knobs;
    knobs.set("oracle-res", 64);
    knobs.set("lazy-prob", 0.5);  // the probability rule reports its own counter
    knobs.set("oracle-refine", 1);  // so do the oracle's finer rays, which are off by default
    Scene flat = test::scene2d();
    test::addSphere(flat, 1, {60, 50, 0}, 2);
    flat.objects.back().motion.kind = MotionKind::Linear;  // TBVs come with motion
    flat.objects.back().motion.velocity = {1, 0, 0};
    flat.objects.back().motion.max_speed = 1;
    flat.finalize();
    Scene deep = test::scene3d();
    test::addSphere(deep, 1, {50, 50, 60}, 2);
    deep.finalize();
    uint32_t reported = 0;
    for (const Scene* scene : {&flat, &deep})
        for (const std::string& name : algorithmNames(scene->dimensions)) {
            auto culler = test::makeOrDie(name, knobs);
            culler->reset(*scene);
            FrameResult out;
            culler->cull(*scene, cameraAt(*scene, 0.0), 0.0, out);
            reported |= out.stats.present;
        }
    for (int c = 0; c < kCounterCount; ++c)
        EXPECT_TRUE((reported >> c) & 1u) << counterName(Counter(c)) << " is reported by none";
}

TEST(Registry, TheReferenceResolutionIsTheOracles) {
    EXPECT_EQ(referenceAlgorithm(), "exact");
    KnobValues knobs;
    EXPECT_EQ(referenceResolution(knobs), 1024);
    knobs.set("oracle-res", 640);
    EXPECT_EQ(referenceResolution(knobs), 640);
}

// The window's start and fallbacks are registered algorithms; the default
// runs on both dimensions and the last resort too, so a scene always gets one.
TEST(Registry, TheDefaultAndLastResortAlgorithmsRunOnEveryDimension) {
    for (const std::string& name : {defaultAlgorithm(), lastResortAlgorithm()}) {
        const AlgorithmEntry* algorithm = nullptr;
        ASSERT_NE(familyOfAlgorithm(name, &algorithm), nullptr) << name;
        EXPECT_EQ(algorithm->dimensions, kRunsBoth) << name;
    }
    EXPECT_NE(defaultAlgorithm(), referenceAlgorithm());
}

TEST(Registry, OnlyFamiliesThatDrawAnImageTakeATarget) {
    std::string error;
    struct NoTarget : ImageTarget {
        void begin(const Camera&, int, int, bool) override {}
        bool draw(const SceneObject&, int, const glm::dvec3&, const PixelRect&,
                  PixelRect&) override {
            return false;
        }
        void prepare(const Scene&) override {}
        long long countFree(const PixelRect&) const override { return 0; }
        double farthestDepth(const PixelRect&) const override { return 0.0; }
        OcclusionQuery issueQuery(const Aabb&) override { return {}; }
        bool queryAvailable(const OcclusionQuery&) override { return true; }
        bool queryResult(const OcclusionQuery&) override { return true; }
        int queryLatencyFrames() const override { return 0; }
        OcclusionQueryCounts queryCounts() const override { return {}; }
        int outstandingQueries() const override { return 0; }
        void resetQueries() override {}
        int addTriangleSet(const std::vector<glm::dvec3>&) override { return 0; }
        bool drawTriangles(int, int, int, int, const glm::dvec3&, const PixelRect&,
                           PixelRect&) override {
            return false;
        }
    };
    EXPECT_EQ(makeCuller("vfc", KnobValues{}, error, std::make_unique<NoTarget>()), nullptr);
    EXPECT_NE(error.find("vfc draws no image"), std::string::npos) << error;
    auto culler = makeCuller("lazy-grid", KnobValues{}, error, std::make_unique<NoTarget>(),
                             "lazy-grid-test");
    ASSERT_TRUE(culler) << error;
    EXPECT_STREQ(culler->name(), "lazy-grid-test");
}

FamilyEntry toyFamily(const std::string& id, const std::string& algorithm,
                      const std::string& knob) {
    FamilyEntry family;
    family.id = id;
    family.title = "toy";
    family.algorithms = {{algorithm, kRuns3d, "toy"}};
    if (!knob.empty()) {
        Knob k;
        k.flag = knob;
        k.min = 0;
        k.max = 1;
        k.help = "toy";
        family.knobs.push_back(k);
    }
    family.make = [](CullerRequest&) { return std::make_unique<VfcCuller>(); };
    return family;
}

TEST(Registry, AddsAFamilyWithNewNamesOnly) {
    std::string error;
    EXPECT_FALSE(registerFamily(toyFamily("rgvc", "toy-a", ""), error));
    EXPECT_NE(error.find("family 'rgvc'"), std::string::npos) << error;
    EXPECT_FALSE(registerFamily(toyFamily("toy", "vfc", ""), error));
    EXPECT_NE(error.find("'vfc' is taken"), std::string::npos) << error;
    // A family named like another may not take that one's knob.
    EXPECT_FALSE(registerFamily(toyFamily("lazy-toy", "toy-a", "lazy-cell-size"), error));
    EXPECT_NE(error.find("--lazy-cell-size is taken"), std::string::npos) << error;
    FamilyEntry empty = toyFamily("toy", "toy-a", "");
    empty.algorithms.clear();
    EXPECT_FALSE(registerFamily(empty, error));
    // A knob names its family; names, dimensions and -gl are checked.
    EXPECT_FALSE(registerFamily(toyFamily("toy", "toy-a", "cells"), error));
    EXPECT_NE(error.find("--cells must start with 'toy-'"), std::string::npos) << error;
    EXPECT_FALSE(registerFamily(toyFamily("toy", "toy-a", "frames"), error));
    FamilyEntry twice = toyFamily("toy", "toy-a", "toy-knob");
    twice.knobs.push_back(twice.knobs.front());
    EXPECT_FALSE(registerFamily(twice, error));
    EXPECT_NE(error.find("--toy-knob is taken"), std::string::npos) << error;
    EXPECT_FALSE(registerFamily(toyFamily("toy", "toy-a-gl", ""), error));
    EXPECT_NE(error.find("-gl"), std::string::npos) << error;
    FamilyEntry nowhere = toyFamily("toy", "toy-a", "");
    nowhere.algorithms[0].dimensions = 0;
    EXPECT_FALSE(registerFamily(nowhere, error));
    EXPECT_NE(error.find("must run on 2D or 3D scenes or both"), std::string::npos) << error;

    const size_t before = families().size();
    ASSERT_TRUE(registerFamily(toyFamily("toy", "toy-a", "toy-knob"), error)) << error;
    EXPECT_EQ(families().size(), before + 1);
    EXPECT_EQ(algorithmNames(3).back(), "toy-a");
    EXPECT_EQ(algorithmNames(2).back(), "rgvc");
    EXPECT_TRUE(makeCuller("toy-a", KnobValues{}, error));
    ASSERT_TRUE(familyOfKnob("toy-knob"));
    EXPECT_EQ(familyOfKnob("toy-knob")->id, "toy");
    unregisterFamily("toy");
    unregisterFamily("rgvc");  // built in: stays
    EXPECT_EQ(families().size(), before);
    EXPECT_TRUE(findFamily("rgvc"));
    EXPECT_FALSE(findFamily("toy"));
}

}  // namespace
}  // namespace gridcull
