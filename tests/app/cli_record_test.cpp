// `gridcull record` (app/cli_record.cpp): a PNG folder whose frames are the very
// PNGs `shot` writes for those frames, an animated GIF with one frame per scene
// frame, and bad ranges or an existing folder refused with nothing written.
// Needs an X display (xvfb-run in the tests).
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/gif_writer.h"
#include "run_command.h"

namespace gridcull::test {
namespace {

const std::string kSize = " --width 320 --height 200 --oracle-res 96";

std::string scene() {
    return "'" + sourcePath("scenes/walls-2d.json") + "'";
}

TEST(CliRecord, PngFramesAreWhatShotDraws) {
    const std::string folder = scratchDir() + "/record-png";
    std::filesystem::remove_all(folder);
    CommandResult r = runGridcull("record " + scene() + " --algo rgvc --from 6 --to 8 --out '" +
                                  folder + "'" + kSize);
    ASSERT_EQ(r.status, 0) << r.err;
    for (int frame = 6; frame <= 8; ++frame) {
        const std::string recorded = folder + "/frame-0000" + std::to_string(frame) + ".png";
        const std::string shot = scratchDir() + "/record-shot.png";
        r = runGridcull("shot " + scene() + " --algo rgvc --frame " + std::to_string(frame) +
                        " --out '" + shot + "'" + kSize);
        ASSERT_EQ(r.status, 0) << r.err;
        const std::string bytes = readWholeFile(recorded);
        ASSERT_FALSE(bytes.empty()) << recorded;
        EXPECT_EQ(bytes, readWholeFile(shot)) << "frame " << frame;
    }
    EXPECT_FALSE(std::filesystem::exists(folder + "/frame-00005.png"));
    EXPECT_FALSE(std::filesystem::exists(folder + "/frame-00009.png"));

    // The folder exists now: refused, and left as it was.
    r = runGridcull("record " + scene() + " --algo rgvc --from 6 --to 7 --out '" + folder + "'" +
                    kSize);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("exists"), std::string::npos) << r.err;
}

TEST(CliRecord, GifHasOneFramePerSceneFrame) {
    const std::string gif = scratchDir() + "/record.gif";
    std::filesystem::remove(gif);
    const CommandResult r = runGridcull("record " + scene() +
                                        " --algo vfc --from 3 --to 7 --out '" + gif + "'" + kSize);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string bytes = readWholeFile(gif);
    ASSERT_GT(bytes.size(), 100u);
    EXPECT_EQ(bytes.substr(0, 6), "GIF89a");
    EXPECT_EQ(bytes.back(), '\x3b');  // the trailer
    // Each frame of an animated GIF carries a graphic control extension (its delay).
    size_t frames = 0;
    for (size_t at = bytes.find("\x21\xf9\x04"); at != std::string::npos;
         at = bytes.find("\x21\xf9\x04", at + 1))
        ++frames;
    EXPECT_EQ(frames, 5u);
}

TEST(CliRecord, BadRangesAreRefusedWithNothingWritten) {
    const std::string gif = scratchDir() + "/record-bad.gif";
    std::filesystem::remove(gif);
    for (const char* range : {" --from 9 --to 3", " --from 0 --to 100000", " --from -1"}) {
        const CommandResult r =
            runGridcull("record " + scene() + " --algo vfc" + range + " --out '" + gif + "'");
        EXPECT_EQ(r.status, 2) << range << "\n" << r.err;
        EXPECT_FALSE(r.err.empty());
        EXPECT_FALSE(std::filesystem::exists(gif)) << range;
    }
}

// Flat colours (the panels') come out exact; a frame of many colours is
// reduced to a palette of 256 at most, each pixel near its colour.
TEST(GifQuantize, FlatColoursExactAtMost256) {
    std::vector<uint8_t> rgba;
    for (int i = 0; i < 1000; ++i) {
        const uint8_t shade = uint8_t(i % 3 == 0 ? 37 : 200);
        rgba.insert(rgba.end(), {shade, uint8_t(255 - shade), 90, 255});
    }
    std::vector<uint8_t> palette, indices;
    quantizeFrame(rgba, palette, indices);
    ASSERT_EQ(indices.size(), 1000u);
    for (size_t i = 0; i < indices.size(); ++i)
        for (int c = 0; c < 3; ++c)
            ASSERT_EQ(palette[indices[i] * 3 + size_t(c)], rgba[i * 4 + size_t(c)]);

    rgba.clear();
    for (int i = 0; i < 256 * 256; ++i)
        rgba.insert(rgba.end(), {uint8_t(i & 255), uint8_t(i >> 8), uint8_t((i * 7) & 255), 255});
    quantizeFrame(rgba, palette, indices);
    EXPECT_LE(palette.size(), 256u * 3);
    int worst = 0;
    for (size_t i = 0; i < indices.size(); ++i)
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(palette[indices[i] * 3 + size_t(c)]) -
                                             int(rgba[i * 4 + size_t(c)])));
    EXPECT_LE(worst, 160);  // 65536 colours into 256: coarse, but each pixel's nearest
}

}  // namespace
}  // namespace gridcull::test

namespace gridcull::test {
namespace {

// A lesson recorded: one PNG per step and per value of a step's animation, the
// step's last image the very PNG `shot --lesson --step` draws.
TEST(CliRecord, ALessonIsRecordedStepByStepWithItsAnimation) {
    const std::string dir = scratchDir() + "/record-lesson";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string lesson = dir + "/lesson.json";
    std::ofstream(lesson) << R"({"title": "t", "scene": ")" << sourcePath("scenes/walls-2d.json")
                          << R"(", "steps": [
        {"title": "one", "caption": "The first step.", "section": "none", "algo": "rgvc",
         "frame": 4, "overlays": "traversal",
         "animate": {"flag": "rgvc-layer", "from": 1, "to": 3, "seconds_per_value": 0.1}},
        {"title": "two", "caption": "The second step.", "section": "none", "frame": 6,
         "compare": "vfc"}]})";
    const std::string out = dir + "/frames";
    CommandResult r = runGridcull("record --lesson '" + lesson + "' --out '" + out + "'" + kSize);
    ASSERT_EQ(r.status, 0) << r.err;
    for (const char* name : {"step-001-0000.png", "step-001-0001.png", "step-001-0002.png",
                             "step-002-0000.png"})
        EXPECT_TRUE(std::filesystem::exists(out + "/" + name)) << name;
    EXPECT_FALSE(std::filesystem::exists(out + "/step-001-0003.png")) << "values 1, 2, 3 only";
    const std::string shot = dir + "/step1.png";
    r = runGridcull("shot --lesson '" + lesson + "' --step 1 --out '" + shot + "'" + kSize);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(readWholeFile(out + "/step-001-0002.png"), readWholeFile(shot));
    EXPECT_NE(readWholeFile(out + "/step-001-0000.png"), readWholeFile(shot))
        << "the animation's first value differs from its last";
    // --from with a lesson is refused.
    r = runGridcull("record --lesson '" + lesson + "' --from 2 --out '" + dir + "/x.gif'" + kSize);
    EXPECT_EQ(r.status, 2);
}

}  // namespace
}  // namespace gridcull::test
