// A family added through the registries alone (the test-only toy family,
// tests/common/toy_family) gets the whole command line for free: its algorithm in
// --algo, its knob as a flag with its range checked and in bench's
// NAME:FLAG=VALUE entries, its knob in `gridcull knobs`, its view flag in shot.
#include <algorithm>

#include <gtest/gtest.h>

#include "run_command.h"

namespace gridcull::test {
namespace {

CommandResult runToy(const std::string& args) {
    return runCommand(std::string("'") + GRIDCULL_TOY_EXE + "' " + args);
}

TEST(ToyFamilyCli, TheRegistryEntryBringsTheAlgorithmAndItsKnob) {
    CommandResult r = runToy("knobs");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("Toy family (tests only)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--toy-count"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--toy-labels"), std::string::npos) << r.out;
    r = runToy("cull --help");
    EXPECT_NE(r.out.find("toy-nearest"), std::string::npos);
    EXPECT_NE(r.out.find("--toy-count N"), std::string::npos);

    const std::string scene = "'" + sourcePath("scenes/walls-2d.json") + "'";
    r = runToy("cull " + scene + " --algo toy-nearest --toy-count 3 --frames 2");
    ASSERT_EQ(r.status, 0) << r.err;
    // Two lines, each with a PVS of three ids.
    size_t lines = 0;
    for (size_t at = r.out.find("\"pvs\": ["); at != std::string::npos;
         at = r.out.find("\"pvs\": [", at + 1)) {
        const size_t end = r.out.find(']', at);
        const std::string list = r.out.substr(at, end - at);
        EXPECT_EQ(std::count(list.begin(), list.end(), ','), 2) << list;
        ++lines;
    }
    EXPECT_EQ(lines, 2u);

    r = runToy("bench " + scene +
               " --algo toy-nearest:toy-count=2,toy-nearest:toy-count=6 "
               "--frames 3 --runs 1 --no-quality");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("toy-nearest:toy-count=2 "), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("toy-count=5"), std::string::npos) << "the options line names it";

    r = runToy("cull " + scene + " --algo toy-nearest --toy-count 0");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--toy-count: expected an integer from 1 to 1000, got '0'"),
              std::string::npos)
        << r.err;
    // The executable without the family knows neither.
    r = runGridcull("cull " + scene + " --algo toy-nearest");
    EXPECT_EQ(r.status, 2);
    r = runGridcull("cull " + scene + " --algo vfc --toy-count 3");
    EXPECT_EQ(r.status, 2);
}

}  // namespace
}  // namespace gridcull::test
