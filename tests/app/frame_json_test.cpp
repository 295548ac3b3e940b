#include "app/frame_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace gridcull {
namespace {

TEST(FrameJson, MatchesTheSpecAndReadsBackExactly) {
    Camera cam;
    cam.dimensions = 3;
    cam.position = {0.1, 2, -3.5};
    cam.target = {1e-7, 1e7, 0.3333333333333333};
    FrameResult r;
    r.pvs = {3, 17, 42};
    r.stats.cull_ms = 0.31;
    r.stats.set(Counter::VoxelsVisited, 5120);
    r.stats.set(Counter::TbvExpired, 2);
    std::string line;
    appendFrameJson(line, 12, 0.48, "rgvc", cam, r);
    ASSERT_EQ(line.back(), '\n');
    EXPECT_EQ(line.find('\n'), line.size() - 1) << "one line per frame";
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["frame"], 12);
    EXPECT_EQ(j["t"].get<double>(), 0.48);
    EXPECT_EQ(j["algo"], "rgvc");
    EXPECT_EQ(j["camera"]["position"][0].get<double>(), 0.1);
    EXPECT_EQ(j["camera"]["target"][2].get<double>(), 0.3333333333333333);
    EXPECT_EQ(j["pvs"], nlohmann::json::parse("[3, 17, 42]"));
    EXPECT_EQ(j["stats"]["cull_ms"].get<double>(), 0.31);
    EXPECT_EQ(j["stats"]["voxels_visited"], 5120);
    EXPECT_EQ(j["stats"]["tbv_expired"], 2);
    EXPECT_FALSE(j["stats"].contains("tbv_created")) << "only reported counters appear";
}

TEST(FrameJson, TwoDimensionalCameraHasTwoNumbers) {
    Camera cam;
    cam.dimensions = 2;
    FrameResult r;
    std::string line;
    appendFrameJson(line, 0, 0.0, "exact", cam, r);
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["camera"]["position"].size(), 2u);
    EXPECT_TRUE(j["pvs"].empty());
    EXPECT_FALSE(j.contains("sub_sample_visible"));  // only an oracle that asks has them
}

TEST(FrameJson, TheOraclesSubSampleObjectsAreListed) {
    Camera cam;
    FrameResult r;
    r.pvs = {1};
    r.sub_sample_visible = {4};
    r.sub_sample_undecided = {2, 7};
    r.stats.set(Counter::SubSampleCandidates, 3);
    r.stats.set(Counter::SubSampleVisible, 1);
    r.stats.set(Counter::SubSampleUndecided, 2);
    std::string line;
    appendFrameJson(line, 0, 0.0, "exact", cam, r);
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["sub_sample_visible"], nlohmann::json({4}));
    EXPECT_EQ(j["sub_sample_undecided"], nlohmann::json({2, 7}));
    EXPECT_EQ(j["stats"]["sub_sample_undecided"], 2);
}

}  // namespace
}  // namespace gridcull
