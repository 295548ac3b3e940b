// Golden-image tests of `gridcull shot` (README.md, "Screenshot tests"). Each
// case of cases.txt is rendered by the real executable with Mesa's software
// renderer (under xvfb-run when there is no X display) and compared with
// screenshots/NAME.png: a pixel fails when a channel differs by more than
// kChannelTolerance, a case fails when more than kMaxFailingFraction of its
// pixels fail. On failure the actual, expected and diff images are written to
// the build tree's output folder. Regenerate goldens: scripts/update-goldens.sh.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/screenshots/png_compare.h"

namespace gridcull {
namespace {

constexpr int kChannelTolerance = 5;           // of 255
constexpr double kMaxFailingFraction = 0.001;  // 0.1% of the pixels

struct ShotCase {
    std::string name, scene;
    int frame = 0;
    std::string view, algo;
    int width = 0, height = 0;
    std::string extra;  // the rest of the line: more shot flags, passed as they are
    std::string exe = GRIDCULL_EXE;
};

// A case whose flags start with this is drawn by gridcull-toy, the executable
// with the test-only toy family registered (tests/common/toy_family).
constexpr const char* kViaToy = "via:gridcull-toy";

// gtest names cases by this instead of dumping their bytes.
void PrintTo(const ShotCase& c, std::ostream* os) {
    *os << c.name;
}

std::vector<ShotCase> loadCases() {
    std::vector<ShotCase> cases;
    std::ifstream in(GRIDCULL_SCREENSHOT_CASES);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        ShotCase c;
        if (fields >> c.name >> c.scene >> c.frame >> c.view >> c.algo >> c.width >> c.height) {
            std::getline(fields, c.extra);
            const size_t via = c.extra.find(kViaToy);
            if (via != std::string::npos) {
                c.extra.erase(via, std::string(kViaToy).size());
                c.exe = GRIDCULL_TOY_EXE;
            }
            cases.push_back(c);
        }
    }
    return cases;
}

std::string quoted(const std::string& s) {
    return "'" + s + "'";
}

// Runs the shot; returns the exit status and fills `log` with its output.
int runShot(const ShotCase& c, const std::string& out_png, std::string& log) {
    namespace fs = std::filesystem;
    const fs::path source(GRIDCULL_SOURCE_DIR);
    const std::string log_path = out_png + ".log";
    // From the source tree: paths in a case's flags (a lesson file) are relative to it.
    std::string command = "cd " + quoted(source.string()) + " && LIBGL_ALWAYS_SOFTWARE=1 ";
    const char* display = std::getenv("DISPLAY");
    if (!display || !*display) command += "xvfb-run -a -s '-screen 0 1280x720x24' ";
    command += quoted(c.exe) + " shot " + quoted((source / c.scene).string()) + " --frame " +
               std::to_string(c.frame) + " --view " + c.view + " --algo " + c.algo + " --width " +
               std::to_string(c.width) + " --height " + std::to_string(c.height) + " " + c.extra +
               " --out " + quoted(out_png) + " > " + quoted(log_path) + " 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(log_path);
    std::stringstream text;
    text << in.rdbuf();
    log = text.str();
    return status;
}

class ScreenshotTest : public ::testing::TestWithParam<ShotCase> {};

TEST_P(ScreenshotTest, MatchesGolden) {
    namespace fs = std::filesystem;
    const ShotCase& c = GetParam();
    const fs::path out_dir(GRIDCULL_SCREENSHOT_OUTPUT);
    fs::create_directories(out_dir);
    const std::string actual_path = (out_dir / (c.name + ".actual.png")).string();
    const std::string expected_copy = (out_dir / (c.name + ".expected.png")).string();
    const std::string diff_path = (out_dir / (c.name + ".diff.png")).string();
    const std::string golden_path =
        (fs::path(GRIDCULL_SOURCE_DIR) / "screenshots" / (c.name + ".png")).string();
    for (const std::string& p : {actual_path, expected_copy, diff_path}) fs::remove(p);

    std::string log;
    const int status = runShot(c, actual_path, log);
    ASSERT_EQ(status, 0) << "gridcull shot failed:\n" << log;

    RgbaImage actual, expected;
    std::string error;
    ASSERT_TRUE(readPng(actual_path, actual, error)) << error;
    EXPECT_EQ(actual.width, c.width);
    EXPECT_EQ(actual.height, c.height);
    if (!fs::exists(golden_path)) {
        FAIL() << "no golden " << golden_path << "\n  actual: " << actual_path
               << "\n  look at it, then run scripts/update-goldens.sh to create the golden";
    }
    ASSERT_TRUE(readPng(golden_path, expected, error)) << error;
    const ImageDiff diff = compareImages(actual, expected, kChannelTolerance);
    const int64_t pixels = int64_t(expected.width) * expected.height;
    const bool ok = diff.same_size && double(diff.failing_pixels) <= kMaxFailingFraction * pixels;
    if (ok) {
        fs::remove(actual_path);
        fs::remove(actual_path + ".log");
        return;
    }
    fs::copy_file(golden_path, expected_copy, fs::copy_options::overwrite_existing);
    if (diff.same_size) writePng(diff_path, diff.diff);
    ADD_FAILURE()
        << c.name << ": "
        << (diff.same_size
                ? std::to_string(diff.failing_pixels) + " of " + std::to_string(pixels) +
                      " pixels differ by more than " + std::to_string(kChannelTolerance) +
                      "/255 (max " + std::to_string(diff.max_channel_difference) + ")"
                : std::string("image sizes differ"))
        << "\n  actual:   " << actual_path << "\n  expected: " << expected_copy
        << "\n  diff:     " << diff_path
        << "\n  if the change is intended, look at it, then run scripts/update-goldens.sh";
}

std::string caseName(const ::testing::TestParamInfo<ShotCase>& info) {
    std::string name = info.param.name;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Goldens, ScreenshotTest, ::testing::ValuesIn(loadCases()), caseName);

// The case list itself: an empty or unreadable list must not pass silently.
TEST(ScreenshotCases, ListIsReadable) {
    const std::vector<ShotCase> cases = loadCases();
    ASSERT_FALSE(cases.empty()) << "no cases in " << GRIDCULL_SCREENSHOT_CASES;
    for (const ShotCase& c : cases) {
        EXPECT_TRUE(std::filesystem::exists(std::filesystem::path(GRIDCULL_SOURCE_DIR) / c.scene))
            << c.name << ": scene " << c.scene;
    }
}

}  // namespace
}  // namespace gridcull
