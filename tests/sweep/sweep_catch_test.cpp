// The sweep must catch a false cull: a test-only family, registered at run
// time as any family is, whose `drop-first` culler is vfc minus the smallest
// id of its PVS (one object it may well see). The sweep takes it from the
// registry with the others, reports its false culls and no one else's, writes
// each failing scene as a file, and that file replays the failure: the same
// frame and ids when the scene is loaded and checked again.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/sweep/sweep_run.h"
#include "tests/sweep/sweep_scenes.h"

namespace gridcull {
namespace {

// vfc, broken: `drop-first` drops the smallest id of the PVS, `reversed`
// hands the PVS out in descending order (against the Culler contract).
class BrokenCuller final : public Culler {
public:
    BrokenCuller(std::unique_ptr<Culler> vfc, bool reversed)
        : vfc_(std::move(vfc)), reversed_(reversed) {}
    const char* name() const override { return reversed_ ? "reversed" : "drop-first"; }
    void reset(const Scene& scene) override { vfc_->reset(scene); }
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override {
        vfc_->cull(scene, camera, t, out);
        if (reversed_)
            std::reverse(out.pvs.begin(), out.pvs.end());
        else if (!out.pvs.empty())
            out.pvs.erase(out.pvs.begin());
    }

private:
    std::unique_ptr<Culler> vfc_;
    bool reversed_;
};

// Registers the broken family for one test and removes it after.
class SweepCatch : public ::testing::Test {
protected:
    void SetUp() override {
        FamilyEntry family;
        family.id = "sweep-broken";
        family.title = "A broken culler for the sweep's test";
        family.algorithms = {{"drop-first", kRunsBoth, "vfc minus its smallest id"},
                             {"reversed", kRunsBoth, "vfc in descending order"}};
        family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
            std::string error;
            return std::make_unique<BrokenCuller>(makeCuller("vfc", *request.knobs, error),
                                                  request.algorithm == "reversed");
        };
        std::string error;
        ASSERT_TRUE(registerFamily(std::move(family), error)) << error;
        out_dir_ = ::testing::TempDir() + "sweep-catch-" + std::to_string(::getpid());
        std::filesystem::create_directories(out_dir_);
    }
    void TearDown() override {
        unregisterFamily("sweep-broken");
        std::error_code ec;
        std::filesystem::remove_all(out_dir_, ec);
    }
    std::string out_dir_;
};

TEST_F(SweepCatch, ReportsTheBrokenCullerAndWritesAReplayableScene) {
    bool listed = false;
    for (const sweep::SweepAlgorithm& a : sweep::conservativeAlgorithms())
        listed = listed || a.name == "drop-first";
    EXPECT_TRUE(listed) << "the sweep takes every non-reference algorithm from the registry";

    sweep::SweepOptions options;
    options.base_seed = 100;
    options.scenes = sweep::kSceneKinds;  // one scene of each kind
    options.threads = 2;
    options.resolution = 64;
    options.out_dir = out_dir_;
    options.algorithms = {{"vfc", 0}, {"drop-first", 0}};
    options.progress_seconds = 0.0;
    const sweep::SweepReport report = sweep::runSweep(options, nullptr);

    EXPECT_EQ(report.scenes, sweep::kSceneKinds);
    EXPECT_TRUE(report.errors.empty()) << report.errors.front();
    EXPECT_EQ(report.tallies[0].false_culls, 0) << "vfc is conservative";
    EXPECT_GT(report.tallies[1].false_culls, 0) << "drop-first drops what the oracle sees";
    ASSERT_FALSE(report.failures.empty());

    for (const sweep::SweepFailure& f : report.failures) {
        SCOPED_TRACE("seed " + std::to_string(f.seed));
        EXPECT_EQ(f.cull.algo, "drop-first");
        ASSERT_FALSE(f.file.empty());
        EXPECT_EQ(sweep::replayCommand(f.file, "drop-first", 64),
                  "gridcull cull " + f.file + " --algo drop-first --oracle-res 64");
        const SceneLoadResult loaded = loadSceneFile(f.file);
        ASSERT_TRUE(loaded.scene) << loaded.errors.front();
        const sweep::SceneCheck again =
            sweep::checkScene(*loaded.scene, {{"drop-first", 0}}, sweep::sweepKnobs(64));
        ASSERT_EQ(again.false_culls.size(), 1u) << "the file replays the failure";
        EXPECT_EQ(again.false_culls[0].frame, f.cull.frame);
        EXPECT_EQ(again.false_culls[0].ids, f.cull.ids);
    }

    // The report names the failure and how to replay it.
    std::FILE* text = std::tmpfile();
    sweep::printReport(report, options, text);
    std::rewind(text);
    std::string printed(1 << 16, '\0');
    printed.resize(std::fread(printed.data(), 1, printed.size(), text));
    std::fclose(text);
    EXPECT_NE(printed.find("FALSE CULL: drop-first, seed "), std::string::npos) << printed;
    EXPECT_NE(printed.find("replay: gridcull cull " + report.failures[0].file +
                           " --algo drop-first --oracle-res 64"),
              std::string::npos)
        << printed;
}

// A miss within an algorithm's late_frames allowance is not a false cull; the
// same misses held to 0 late frames are.
TEST_F(SweepCatch, LateFramesAllowanceIsHonoured) {
    Scene scene;
    std::string error;
    ASSERT_TRUE(
        sweep::replayable(sweep::generatedScene(103), out_dir_ + "/late.json", scene, error))
        << error;
    const KnobValues knobs = sweep::sweepKnobs(64);
    const sweep::SceneCheck strict = sweep::checkScene(scene, {{"drop-first", 0}}, knobs);
    const sweep::SceneCheck lenient =
        sweep::checkScene(scene, {{"drop-first", scene.frames}}, knobs);
    EXPECT_GT(strict.tallies[0].false_culls, 0);
    EXPECT_EQ(lenient.tallies[0].false_culls, 0);
    EXPECT_EQ(lenient.tallies[0].frames, scene.frames);
}

// A PVS out of order is reported as an error, not compared as if sorted.
TEST_F(SweepCatch, UnsortedPvsIsAnError) {
    Scene scene;
    std::string error;
    ASSERT_TRUE(
        sweep::replayable(sweep::generatedScene(103), out_dir_ + "/order.json", scene, error))
        << error;
    const sweep::SceneCheck check =
        sweep::checkScene(scene, {{"reversed", 0}}, sweep::sweepKnobs(64));
    ASSERT_EQ(check.errors.size(), 1u);
    EXPECT_NE(check.errors[0].find("reversed: frame "), std::string::npos) << check.errors[0];
    EXPECT_NE(check.errors[0].find("not sorted and unique"), std::string::npos) << check.errors[0];
}

}  // namespace
}  // namespace gridcull
