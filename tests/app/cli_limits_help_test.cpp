// Every limit the program enforces on scenes and culler options is stated in
// the help of the commands that apply it (docs/LIMITS.md lists them all), with
// the values of the constants that enforce it.
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "culling/io/scene_loader.h"
#include "culling/oracle/exact_oracle.h"
#include "grid/regular_grid.h"
#include "run_command.h"

namespace gridcull::test {
namespace {

TEST(CliLimitsHelp, CullingCommandsStateTheLimits) {
    const std::string voxels = std::to_string(kMaxGridVoxels);
    char coordinate[32];
    std::snprintf(coordinate, sizeof coordinate, "%.0f", kMaxSceneCoordinate);
    for (const char* cmd : {"cull --help", "bench --help", "shot --help", "view --help"}) {
        const CommandResult r = runGridcull(cmd);
        ASSERT_EQ(r.status, 0) << cmd;
        for (const std::string& needle :
             {std::string(coordinate), voxels, std::string("3D: in (0, 180); 2D: in (0, 360]"),
              std::string("0 < near < far"), std::to_string(kMaxSceneObjects),
              std::to_string(kMaxSceneFrames), std::to_string(kMaxOracleResolution),
              std::to_string(kMaxOracleRaysPerTurn), std::string("docs/LIMITS.md")}) {
            EXPECT_NE(r.out.find(needle), std::string::npos) << cmd << " lacks " << needle;
        }
    }
}

TEST(CliLimitsHelp, OracleFlagsOutsideTheirRangeAreRejected) {
    const std::string scene = "'" + sourcePath("scenes/walls-2d.json") + "'";
    for (const std::string& flag : {std::string("--oracle-res 15"),
                                    "--oracle-res " + std::to_string(kMaxOracleResolution + 1),
                                    std::string("--oracle-rays -1"),
                                    "--oracle-rays " + std::to_string(kMaxOracleRaysPerTurn + 1)}) {
        const CommandResult r = runGridcull("cull " + scene + " --algo exact --frames 1 " + flag);
        EXPECT_EQ(r.status, 2) << flag << "\n" << r.err;
    }
}

}  // namespace
}  // namespace gridcull::test
