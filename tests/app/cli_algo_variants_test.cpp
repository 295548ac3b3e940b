// bench's --algo entries with options of their own (app/cli.h parseAlgoVariants):
// the same algorithm at several settings in one run, every value checked like the
// flag it stands for.
#include <gtest/gtest.h>

#include "app/cli.h"

namespace gridcull {
namespace {

TEST(CliAlgoVariants, EachEntryTakesTheCommandOptionsAndItsOwnOverThem) {
    CullerOptions base;
    base.oracle_resolution = 640;
    base.lazy_cell_size = 16;
    std::vector<AlgoVariant> variants;
    std::string error;
    ASSERT_TRUE(parseAlgoVariants("vfc,lazy-grid:cell-size=8,lazy-grid:cell-size=64:lazy-prob=0.5",
                                  base, variants, error))
        << error;
    ASSERT_EQ(variants.size(), 3u);
    EXPECT_EQ(variants[0].label, "vfc");
    EXPECT_EQ(variants[0].options.lazy_cell_size, 16);
    EXPECT_EQ(variants[1].name, "lazy-grid");
    EXPECT_EQ(variants[1].label, "lazy-grid:cell-size=8");
    EXPECT_EQ(variants[1].options.lazy_cell_size, 8);
    EXPECT_EQ(variants[1].options.oracle_resolution, 640);
    EXPECT_EQ(variants[2].options.lazy_cell_size, 64);
    EXPECT_DOUBLE_EQ(variants[2].options.lazy_probability_threshold, 0.5);
}

TEST(CliAlgoVariants, BadEntriesAreNamedWithWhatWasExpected) {
    std::vector<AlgoVariant> variants;
    std::string error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:cell-size=0", {}, variants, error));
    EXPECT_NE(error.find("lazy-grid:cell-size=0"), std::string::npos) << error;
    EXPECT_NE(error.find("1 to 1024"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:cell-size", {}, variants, error));
    EXPECT_NE(error.find("FLAG=VALUE"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-gird:cell-size=8", {}, variants, error));
    EXPECT_NE(error.find("lazy-gird"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:frames=3", {}, variants, error));
    EXPECT_NE(error.find("frames"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("", {}, variants, error));
}

}  // namespace
}  // namespace gridcull
