// bench's --algo entries with knobs of their own (app/cli.h parseAlgoVariants):
// the same algorithm at several settings in one run, every value checked like the
// flag it stands for.
#include <gtest/gtest.h>

#include "app/cli.h"

namespace gridcull {
namespace {

TEST(CliAlgoVariants, EachEntryTakesTheCommandKnobsAndItsOwnOverThem) {
    KnobValues base;
    base.set("oracle-res", 640);
    base.set("lazy-cell-size", 16);
    std::vector<AlgoVariant> variants;
    std::string error;
    ASSERT_TRUE(parseAlgoVariants(
        "vfc,lazy-grid:lazy-cell-size=8,lazy-grid:lazy-cell-size=64:lazy-prob=0.5,lazy-grid-gl",
        base, variants, error))
        << error;
    ASSERT_EQ(variants.size(), 4u);
    EXPECT_EQ(variants[0].label, "vfc");
    EXPECT_EQ(variants[0].knobs.set_values().at("lazy-cell-size"), 16);
    EXPECT_EQ(variants[1].name, "lazy-grid");
    EXPECT_EQ(variants[1].label, "lazy-grid:lazy-cell-size=8");
    EXPECT_EQ(variants[1].knobs.set_values().at("lazy-cell-size"), 8);
    EXPECT_EQ(variants[1].knobs.set_values().at("oracle-res"), 640);
    EXPECT_EQ(variants[2].knobs.set_values().at("lazy-cell-size"), 64);
    EXPECT_DOUBLE_EQ(variants[2].knobs.set_values().at("lazy-prob"), 0.5);
    EXPECT_EQ(variants[3].name, "lazy-grid-gl");
}

TEST(CliAlgoVariants, BadEntriesAreNamedWithWhatWasExpected) {
    std::vector<AlgoVariant> variants;
    std::string error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:lazy-cell-size=0", {}, variants, error));
    EXPECT_NE(error.find("lazy-grid:lazy-cell-size=0"), std::string::npos) << error;
    EXPECT_NE(error.find("1 to 1024"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:lazy-cell-size", {}, variants, error));
    EXPECT_NE(error.find("FLAG=VALUE"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-gird:lazy-cell-size=8", {}, variants, error));
    EXPECT_NE(error.find("lazy-gird"), std::string::npos) << error;
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:frames=3", {}, variants, error));
    EXPECT_NE(error.find("'frames' is not a knob"), std::string::npos) << error;
    // The old, family-less flag names are gone: a knob says whose it is.
    EXPECT_FALSE(parseAlgoVariants("lazy-grid:cell-size=8", {}, variants, error));
    EXPECT_FALSE(parseAlgoVariants("rgvc:grid-res=64", {}, variants, error));
    EXPECT_FALSE(parseAlgoVariants("vfc-gl", {}, variants, error));  // draws no image
    // Another family's knob would do nothing for the entry; the oracle's may go with any.
    EXPECT_FALSE(parseAlgoVariants("vfc:lazy-cell-size=8", {}, variants, error));
    EXPECT_NE(error.find("--lazy-cell-size is a knob of"), std::string::npos) << error;
    EXPECT_TRUE(parseAlgoVariants("lazy-grid-gl:lazy-cell-size=8,rgvc:oracle-rays=4096", {},
                                  variants, error))
        << error;
    EXPECT_FALSE(parseAlgoVariants("", {}, variants, error));
}

}  // namespace
}  // namespace gridcull
