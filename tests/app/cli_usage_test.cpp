// The command line's contract (README.md, "Command line"): help, version, exit statuses.
#include <gtest/gtest.h>

#include "run_command.h"

namespace gridcull::test {
namespace {

TEST(CliUsage, VersionAndHelpExitZero) {
    CommandResult r = runGridcull("--version");
    EXPECT_EQ(r.status, 0);
    EXPECT_NE(r.out.find("gridcull "), std::string::npos);
    for (const char* cmd :
         {"--help", "cull --help", "bench --help", "shot --help", "view --help", "record --help"}) {
        r = runGridcull(cmd);
        EXPECT_EQ(r.status, 0) << cmd;
        EXPECT_NE(r.out.find("usage"), std::string::npos) << cmd;
        EXPECT_TRUE(r.err.empty()) << cmd << ": " << r.err;
    }
    r = runGridcull("bench --help");
    for (const char* algo : {"all", "vfc", "exact"})
        EXPECT_NE(r.out.find(algo), std::string::npos) << algo;
}

TEST(CliUsage, BadCommandLinesExitTwo) {
    const std::string scene = "'" + sourcePath("scenes/default.json") + "'";
    const std::vector<std::string> cases = {std::string("frobnicate"),
                                            "cull",
                                            "cull " + scene,
                                            "cull " + scene + " --algo nope",
                                            "cull " + scene + " --algo vfc --frames 0",
                                            "cull " + scene + " --algo vfc --frames x",
                                            "cull " + scene + " --algo vfc --bogus",
                                            "cull " + scene + " --algo",
                                            "bench " + scene + " --algo vfc,,all",
                                            "bench " + scene + " --algo vfc --runs -1",
                                            "shot " + scene + " --frame 1",
                                            "shot " + scene + " --out x.png",
                                            "shot " + scene + " --frame 999999 --out x.png",
                                            "cull " + scene + " --algo vfc --oracle-res 3",
                                            "cull " + scene + " --algo rgvc --rgvc-validity 0",
                                            "bench " + scene + " --algo rgvc --rgvc-validity nan",
                                            "bench " + scene + " --algo rgvc --rgvc-grid-res 0",
                                            "bench " + scene + " --algo rgvc --seek 0",
                                            "shot " + scene + " --frame 1 --out x.png --ui-scale 0",
                                            "shot " + scene + " --frame 1 --out x.png --ui-scale 9",
                                            "view " + scene + " --ui-scale x",
                                            "bench " + scene + " --algo rgvc --seek 5,x",
                                            "bench " + scene + " --algo rgvc --seek 999999"};
    for (const std::string& args : cases) {
        const CommandResult r = runGridcull(args);
        EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
        EXPECT_FALSE(r.err.empty()) << args;
    }
}

TEST(CliUsage, MissingSceneFileIsRejectedWithStatusThree) {
    const CommandResult r = runGridcull("cull /nonexistent/scene.json --algo vfc");
    EXPECT_EQ(r.status, 3);
    EXPECT_NE(r.err.find("/nonexistent/scene.json"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gridcull::test
