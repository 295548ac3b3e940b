// Every malformed scene under tests/scenes/bad is rejected by the real executable
// with exit status 3 and a message naming the place (expected.tsv gives the text
// each message must contain), and no command leaves an output file behind.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "run_command.h"
#include "tests/common/bad_scene_manifest.h"

namespace gridcull::test {
namespace {

std::vector<BadScene> readManifest() { return readBadSceneManifest(GRIDCULL_SOURCE_DIR); }

TEST(CliSceneErrors, ManifestListsEveryBadFile) {
    const auto cases = readManifest();
    size_t files = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(sourcePath("tests/scenes/bad"))) {
        if (entry.path().extension() != ".json") continue;
        ++files;
        bool listed = false;
        for (const auto& c : cases) listed = listed || c.file == entry.path().filename();
        EXPECT_TRUE(listed) << entry.path() << " is not in expected.tsv";
    }
    EXPECT_GE(files, 30u);
    EXPECT_EQ(files, cases.size());
}

TEST(CliSceneErrors, EveryBadSceneExitsThreeNamingThePlace) {
    const std::string out_dir = scratchDir();
    for (const auto& c : readManifest()) {
        const std::string scene = "'" + sourcePath("tests/scenes/bad/" + c.file) + "'";
        const std::string jsonl = out_dir + "/bad.jsonl";
        const std::string csv = out_dir + "/bad.csv";
        const std::string png = out_dir + "/bad.png";
        for (const std::string& args :
             {"cull " + scene + " --algo vfc --out '" + jsonl + "'",
              "bench " + scene + " --algo all --csv '" + csv + "'",
              "shot " + scene + " --frame 0 --out '" + png + "'"}) {
            const CommandResult r = runGridcull(args);
            EXPECT_EQ(r.status, 3) << args << "\n" << r.err;
            EXPECT_NE(r.err.find(c.expected), std::string::npos)
                << c.file << ": expected the message to contain '" << c.expected << "', got\n"
                << r.err;
            EXPECT_TRUE(r.out.empty()) << args;
        }
        EXPECT_FALSE(std::filesystem::exists(jsonl)) << c.file;
        EXPECT_FALSE(std::filesystem::exists(csv)) << c.file;
        EXPECT_FALSE(std::filesystem::exists(png)) << c.file;
        for (const auto& entry : std::filesystem::directory_iterator(out_dir))
            EXPECT_EQ(entry.path().string().find(".part-"), std::string::npos) << entry.path();
    }
}

}  // namespace
}  // namespace gridcull::test
