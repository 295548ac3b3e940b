// gridcull trade, run as the real executable: the CSV has a whole row per
// setting with the fronts marked, the plots are written, --target names the
// pick, bad input is refused, and Ctrl-C leaves a CSV of whole rows.
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/trade_sweep.h"
#include "tests/app/run_command.h"

namespace gridcull {
namespace {

std::vector<std::vector<std::string>> readCsv(const std::string& path) {
    std::vector<std::vector<std::string>> rows;
    std::stringstream lines(test::readWholeFile(path));
    std::string line;
    while (std::getline(lines, line)) {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        if (!line.empty() && line.back() == ',') cells.push_back("");
        rows.push_back(cells);
    }
    return rows;
}

bool fileExists(const std::string& path) {
    struct stat st;
    return ::stat(path.c_str(), &st) == 0 && st.st_size > 0;
}

TEST(CliTrade, WritesEverySettingThePlotsAndThePick) {
    const std::string dir = test::scratchDir() + "/trade-city";
    const test::CommandResult r = test::runGridcull(
        "trade '" + test::sourcePath("scenes/city-walk-3d.json") +
        "' --algo vfc,lazy-grid --frames 3 --runs 1 --oracle-res 128 --target 5 --out '" + dir +
        "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto rows = readCsv(dir + "/trade.csv");
    const size_t settings = tradeSettings({"vfc", "lazy-grid"}, {}).size();
    ASSERT_EQ(rows.size(), settings + 1);
    const size_t columns = rows[0].size();
    EXPECT_EQ(rows[0][0], "setting");
    int fronts = 0;
    for (size_t i = 1; i < rows.size(); ++i) {
        EXPECT_EQ(rows[i].size(), columns) << rows[i][0];
        fronts += rows[i][columns - 2] == "1";
    }
    EXPECT_GE(fronts, 2);  // each algorithm has a front of at least one setting
    EXPECT_TRUE(fileExists(dir + "/trade.png"));
    EXPECT_TRUE(fileExists(dir + "/vfc.png"));
    EXPECT_TRUE(fileExists(dir + "/lazy-grid.png"));
    EXPECT_NE(r.out.find("target PVS/exact <= 5 with no false cull:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cheapest of all: lazy-grid"), std::string::npos) << r.out;

    // --replot: the same table and pick from the CSV, with no sweep.
    const std::string scene = "'" + test::sourcePath("scenes/city-walk-3d.json") + "'";
    const test::CommandResult again =
        test::runGridcull("trade " + scene + " --algo vfc --replot --target 5 --out '" + dir + "'");
    ASSERT_EQ(again.status, 0) << again.err;
    const std::string pick = r.out.substr(r.out.find("cheapest of all:"));
    EXPECT_EQ(pick.substr(0, pick.find('\n')),
              again.out.substr(again.out.find("cheapest of all:")).substr(0, pick.find('\n')));
    // A damaged CSV is named by line and column.
    std::string csv = test::readWholeFile(dir + "/trade.csv");
    csv.replace(csv.find('\n') + 1, csv.find(',', csv.find('\n')) - csv.find('\n'), "x,x,x,y,");
    {
        std::ofstream out(dir + "/trade.csv");
        out << csv;
    }
    const test::CommandResult bad =
        test::runGridcull("trade " + scene + " --algo vfc --replot --out '" + dir + "'");
    EXPECT_EQ(bad.status, 1);
    EXPECT_NE(bad.err.find("trade.csv: line 2:"), std::string::npos) << bad.err;
}

TEST(CliTrade, RefusesWhatItCannotSweep) {
    const std::string scene = "'" + test::sourcePath("scenes/city-walk-3d.json") + "'";
    test::CommandResult r = test::runGridcull("trade " + scene + " --algo lazy-grid:lazy-prob=1");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("unknown algorithm 'lazy-grid:lazy-prob=1'"), std::string::npos) << r.err;
    r = test::runGridcull("trade " + scene + " --algo vfc --target 0.5");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--target"), std::string::npos) << r.err;
    r = test::runGridcull("trade '" + test::sourcePath("scenes/figure1-2d.json") +
                          "' --algo lazy-grid");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("3D scenes only"), std::string::npos) << r.err;
}

TEST(CliTrade, CtrlCLeavesACsvOfWholeRows) {
    const std::string dir = test::scratchDir() + "/trade-interrupted";
    // A sweep far longer than the 3 s it is given.
    const test::CommandResult r = test::runCommand(
        "{ timeout --preserve-status -s INT 3 '" + std::string(GRIDCULL_EXE) + "' trade '" +
        test::sourcePath("scenes/city-walk-3d.json") + "' --algo vfc,lazy-grid --runs 5 --out '" +
        dir + "'; echo \"exit $?\"; }");
    // The status is echoed: the test runner reads any status over 128 as a crash.
    ASSERT_NE(r.out.find("exit 130"), std::string::npos) << r.out << r.err;
    EXPECT_NE(r.err.find("interrupted"), std::string::npos) << r.err;
    const auto rows = readCsv(dir + "/trade.csv");
    ASSERT_GE(rows.size(), 1u);
    EXPECT_EQ(rows[0][0], "setting");
    EXPECT_LT(rows.size() - 1, tradeSettings({"vfc", "lazy-grid"}, {}).size());
    for (const auto& row : rows) EXPECT_EQ(row.size(), rows[0].size());
}

}  // namespace
}  // namespace gridcull
