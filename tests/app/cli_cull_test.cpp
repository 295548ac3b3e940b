// `gridcull cull` on the default scene: the spec's line format, and the baselines'
// relation to the oracle at every frame (vfc contains exact, all is every id).
#include <set>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "culling/io/scene_loader.h"
#include "run_command.h"

namespace gridcull::test {
namespace {

constexpr int kFrames = 20;

std::vector<nlohmann::json> cullLines(const std::string& algo) {
    const std::string out = scratchDir() + "/" + algo + ".jsonl";
    const CommandResult r =
        runGridcull("cull '" + sourcePath("scenes/default.json") + "' --algo " + algo +
                    " --frames " + std::to_string(kFrames) + " --out '" + out + "'");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(r.out.empty()) << "with --out nothing goes to stdout";
    std::vector<nlohmann::json> lines;
    std::stringstream in(readWholeFile(out));
    std::string line;
    while (std::getline(in, line)) lines.push_back(nlohmann::json::parse(line));
    return lines;
}

void expectSpecFormat(const nlohmann::json& j, int frame, const std::string& algo, double dt) {
    EXPECT_EQ(j.at("frame").get<int>(), frame);
    EXPECT_NEAR(j.at("t").get<double>(), frame * dt, 1e-12);
    EXPECT_EQ(j.at("algo").get<std::string>(), algo);
    EXPECT_EQ(j.at("camera").at("position").size(), 3u);
    EXPECT_EQ(j.at("camera").at("target").size(), 3u);
    const auto pvs = j.at("pvs").get<std::vector<int>>();
    EXPECT_TRUE(std::is_sorted(pvs.begin(), pvs.end()));
    EXPECT_EQ(std::set<int>(pvs.begin(), pvs.end()).size(), pvs.size()) << "ids repeat";
    EXPECT_GE(j.at("stats").at("cull_ms").get<double>(), 0.0);
}

TEST(CliCull, BaselinesBracketTheOracleOnTheDefaultScene) {
    const Scene scene = defaultScene();
    std::set<int> every_id;
    for (const auto& o : scene.objects) every_id.insert(o.id);

    const auto exact = cullLines("exact");
    const auto vfc = cullLines("vfc");
    const auto all = cullLines("all");
    ASSERT_EQ(exact.size(), size_t(kFrames));
    ASSERT_EQ(vfc.size(), size_t(kFrames));
    ASSERT_EQ(all.size(), size_t(kFrames));
    size_t exact_total = 0, vfc_total = 0;
    for (int f = 0; f < kFrames; ++f) {
        SCOPED_TRACE("frame " + std::to_string(f));
        expectSpecFormat(exact[size_t(f)], f, "exact", scene.dt);
        expectSpecFormat(vfc[size_t(f)], f, "vfc", scene.dt);
        expectSpecFormat(all[size_t(f)], f, "all", scene.dt);
        const auto e = exact[size_t(f)]["pvs"].get<std::vector<int>>();
        const auto v = vfc[size_t(f)]["pvs"].get<std::vector<int>>();
        const auto a = all[size_t(f)]["pvs"].get<std::vector<int>>();
        EXPECT_TRUE(std::includes(v.begin(), v.end(), e.begin(), e.end()))
            << "vfc dropped an object the oracle sees";
        EXPECT_EQ(std::set<int>(a.begin(), a.end()), every_id);
        EXPECT_EQ(exact[size_t(f)]["camera"], vfc[size_t(f)]["camera"]);
        exact_total += e.size();
        vfc_total += v.size();
    }
    // The default scene is built to be densely occluded: the oracle must see
    // something, and far less than the frustum holds.
    EXPECT_GT(exact_total, 0u);
    EXPECT_LT(exact_total, vfc_total);
}

TEST(CliCull, WithoutOutWritesToStandardOutput) {
    const CommandResult r =
        runGridcull("cull '" + sourcePath("scenes/default.json") + "' --algo vfc --frames 3");
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3);
}

TEST(CliCull, TwoDimensionalSceneWritesTwoNumbersPerVector) {
    const CommandResult r =
        runGridcull("cull '" + sourcePath("scenes/walls-2d.json") + "' --algo exact --frames 2");
    ASSERT_EQ(r.status, 0) << r.err;
    std::stringstream in(r.out);
    std::string line;
    std::getline(in, line);
    const auto j = nlohmann::json::parse(line);
    EXPECT_EQ(j["camera"]["position"].size(), 2u);
    EXPECT_FALSE(j["pvs"].empty());
}

TEST(CliBench, PrintsAlgorithmsSideBySideAndWritesCsv) {
    const std::string csv = scratchDir() + "/bench.csv";
    const CommandResult r =
        runGridcull("bench '" + sourcePath("scenes/walls-2d.json") +
                    "' --algo all,vfc,exact --frames 4 --runs 3 --csv '" + csv + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* algo : {"\nall ", "\nvfc ", "\nexact "})
        EXPECT_NE(r.out.find(algo), std::string::npos) << algo << " row missing\n" << r.out;
    EXPECT_NE(r.out.find("pvs/exact"), std::string::npos);
    const std::string text = readWholeFile(csv);
    EXPECT_EQ(text.rfind("algo,frame,t,cull_ms_median", 0), 0u) << text;
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 3 * 4);
    // The oracle against itself has no false culls and a PVS/exact of exactly 1.
    EXPECT_NE(r.out.find("1.000"), std::string::npos) << r.out;
}

// bench --seek: the window's step back into a frame replays from a checkpoint
// (at most its interval of frames), a step forward one frame.
TEST(CliBench, SeekTimesStepsForwardAndBackThroughCheckpoints) {
    const CommandResult r = runGridcull("bench '" + sourcePath("scenes/walls-2d.json") +
                                        "' --algo rgvc,vfc --seek 7,10 --runs 2 --oracle-res 96");
    ASSERT_EQ(r.status, 0) << r.err;
    std::istringstream lines(r.out);
    std::string line;
    int rows = 0;
    while (std::getline(lines, line)) {
        std::istringstream row(line);
        std::string algo;
        int frame = 0, forward_culls = 0, back_culls = 0;
        double fwd = 0, fwd95 = 0, back = 0, back95 = 0, ratio = 0;
        if (!(row >> algo >> frame >> fwd >> fwd95 >> back >> back95 >> ratio >> forward_culls >>
              back_culls))
            continue;
        ++rows;
        EXPECT_EQ(forward_culls, 1) << line;
        // Into 7 from 8: the checkpoint before frame 4, then 4..7; into 10: 8..10.
        EXPECT_EQ(back_culls, frame == 7 ? 4 : 3) << line;
    }
    EXPECT_EQ(rows, 4) << r.out;
    EXPECT_NE(r.out.find("rgvc             checkpoints: "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace gridcull::test
