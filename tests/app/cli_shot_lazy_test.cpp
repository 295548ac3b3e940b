// `gridcull shot`'s lazy grid flags: the view flag --lazy-object names an object
// of the scene, and the family's knobs (--lazy-cell-size) are shot flags like the
// other commands'.
#include <gtest/gtest.h>

#include "run_command.h"

namespace gridcull::test {
namespace {

TEST(CliShotLazy, HelpNamesTheFlagsAndTheView) {
    const CommandResult r = runGridcull("shot --help");
    EXPECT_EQ(r.status, 0);
    for (const char* text : {"--lazy-object N", "--lazy-cell-size N", "main-camera"})
        EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

TEST(CliShotLazy, UnknownObjectOrBadCellSizeExitTwo) {
    const std::string shot = "shot '" + sourcePath("scenes/forest-3d.json") +
                             "' --frame 0 --out '" + scratchDir() + "/never.png' --algo lazy-grid";
    CommandResult r = runGridcull(shot + " --lazy-object 999999");
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_NE(r.err.find("--lazy-object 999999"), std::string::npos) << r.err;
    for (const char* bad :
         {" --lazy-object -1", " --lazy-object x", " --lazy-cell-size 0", " --cell-size 16"}) {
        r = runGridcull(shot + bad);
        EXPECT_EQ(r.status, 2) << bad << "\n" << r.err;
        EXPECT_FALSE(r.err.empty()) << bad;
    }
}

}  // namespace
}  // namespace gridcull::test
