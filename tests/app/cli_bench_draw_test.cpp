// bench --draw gl, run as the real executable: every CSV row's cull + draw is
// its frame, the limit row draws the exact set with no cull time, ratios are
// taken against --baseline, and bad combinations are refused by name.
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/app/run_command.h"

namespace gridcull {
namespace {

std::vector<std::string> splitCsv(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    return cells;
}

int columnOf(const std::vector<std::string>& header, const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
        if (header[i] == name) return int(i);
    return -1;
}

TEST(CliBenchDraw, EveryCsvRowsCullPlusDrawIsItsFrame) {
    const std::string csv = test::scratchDir() + "/bench-draw.csv";
    const test::CommandResult r = test::runGridcull(
        "bench '" + test::sourcePath("scenes/city-walk-3d.json") +
        "' --algo all,vfc,lazy-grid --draw gl --frames 4 --runs 3 --oracle-res 256"
        " --baseline all --csv '" + csv + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("x all"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("x limit"), std::string::npos) << r.out;
    std::stringstream lines(test::readWholeFile(csv));
    std::string line;
    ASSERT_TRUE(std::getline(lines, line));
    const std::vector<std::string> header = splitCsv(line);
    const int algo = columnOf(header, "algo"), cull = columnOf(header, "cull_ms"),
              draw = columnOf(header, "draw_ms"), frame = columnOf(header, "frame_ms"),
              pvs = columnOf(header, "pvs"), exact = columnOf(header, "exact");
    ASSERT_TRUE(algo >= 0 && cull >= 0 && draw >= 0 && frame >= 0 && pvs >= 0 && exact >= 0)
        << line;
    int rows = 0, limit_rows = 0;
    while (std::getline(lines, line)) {
        const std::vector<std::string> cells = splitCsv(line);
        ASSERT_GT(cells.size(), size_t(frame)) << line;
        const double c = std::stod(cells[size_t(cull)]), d = std::stod(cells[size_t(draw)]),
                     f = std::stod(cells[size_t(frame)]);
        // Written to 17 digits, so the sum of the doubles read back is exact.
        EXPECT_EQ(c + d, f) << line;
        EXPECT_GT(d, 0.0) << line;
        if (cells[size_t(algo)] == "limit") {
            ++limit_rows;
            EXPECT_EQ(c, 0.0) << "the limit's cull time is excluded: " << line;
            EXPECT_EQ(cells[size_t(pvs)], cells[size_t(exact)]) << line;
        }
        ++rows;
    }
    EXPECT_EQ(rows, 4 * 4);  // three entries and the limit, four frames each
    EXPECT_EQ(limit_rows, 4);
}

TEST(CliBenchDraw, RefusesWhatItCannotMeasure) {
    const std::string scene = "'" + test::sourcePath("scenes/city-walk-3d.json") + "'";
    test::CommandResult r =
        test::runGridcull("bench " + scene + " --algo vfc --frames 2 --baseline lazy-grid");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--baseline 'lazy-grid' is not a row; the rows are vfc"),
              std::string::npos)
        << r.err;
    r = test::runGridcull("bench " + scene + " --algo vfc --frames 2 --draw gl --no-quality");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--no-quality"), std::string::npos) << r.err;
    r = test::runGridcull("bench " + scene + " --algo vfc --frames 2 --draw vulkan");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("--draw"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace gridcull
