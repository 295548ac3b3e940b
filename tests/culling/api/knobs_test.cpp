// Knobs (culling/api/knobs.h): one description per option drives parsing,
// checking and defaults; a typed table reads a family's struct back.
#include <gtest/gtest.h>

#include "culling/api/knobs.h"

namespace gridcull {
namespace {

struct ToyOptions {
    int cells = 32;
    double fraction = 0.25;
    int side = 0;  // 0: derived
};

const KnobTable<ToyOptions>& toyKnobs() {
    static const KnobTable<ToyOptions> table{
        knob("toy-cells", &ToyOptions::cells, 1, 1024, "cells"),
        knob("toy-fraction", &ToyOptions::fraction, 0.0, 1.0, "a fraction"),
        derivedKnob("toy-side", &ToyOptions::side, 16, 8192, "other", "the other side", "side"),
    };
    return table;
}

TEST(Knobs, DefaultsComeFromTheOptionsStruct) {
    const std::vector<Knob>& knobs = toyKnobs().knobs();
    ASSERT_EQ(knobs.size(), 3u);
    EXPECT_EQ(knobs[0].flag, "toy-cells");
    EXPECT_EQ(knobs[0].kind, KnobKind::Integer);
    EXPECT_EQ(knobs[0].default_value, 32.0);
    EXPECT_EQ(knobs[1].kind, KnobKind::Real);
    EXPECT_EQ(knobs[1].default_value, 0.25);
    EXPECT_EQ(knobs[2].default_value, 0.0);
    EXPECT_EQ(knobValueText(knobs[2], 0.0), "other");
    EXPECT_EQ(knobDefaultText(knobs[2]), "the other side");
    EXPECT_EQ(knobDefaultText(knobs[0]), "32");
    EXPECT_EQ(knobValueText(knobs[2], 640.0), "640");
    EXPECT_EQ(knobValueText(knobs[1], 0.25), "0.25");
}

TEST(Knobs, ReadAppliesOnlyTheValuesSet) {
    KnobValues values;
    ToyOptions options = toyKnobs().read(values);
    EXPECT_EQ(options.cells, 32);
    EXPECT_EQ(options.fraction, 0.25);
    values.set("toy-cells", 8);
    values.set("toy-fraction", 0.5);
    values.set("other-family-knob", 3);  // someone else's: ignored
    options = toyKnobs().read(values);
    EXPECT_EQ(options.cells, 8);
    EXPECT_EQ(options.fraction, 0.5);
    EXPECT_EQ(options.side, 0);
    values.unset("toy-cells");
    EXPECT_EQ(toyKnobs().read(values).cells, 32);
}

TEST(Knobs, ParsingChecksKindAndRangeAndSaysWhatWasExpected) {
    const Knob& cells = toyKnobs().knobs()[0];
    const Knob& fraction = toyKnobs().knobs()[1];
    double v = -1.0;
    std::string error;
    EXPECT_TRUE(parseKnobValue(cells, "1024", v, error));
    EXPECT_EQ(v, 1024.0);
    EXPECT_TRUE(parseKnobValue(fraction, "1e-1", v, error));
    EXPECT_EQ(v, 0.1);
    for (const char* bad : {"0", "1025", "1.5", "", "8x", "nan", "-3"}) {
        EXPECT_FALSE(parseKnobValue(cells, bad, v, error)) << bad;
        EXPECT_EQ(error,
                  std::string("option --toy-cells: expected an integer from 1 to 1024, got '") +
                      bad + "'");
    }
    for (const char* bad : {"nan", "inf", "1.0001", "-0.1", "1e999", "0.5.5"}) {
        EXPECT_FALSE(parseKnobValue(fraction, bad, v, error)) << bad;
        EXPECT_NE(error.find("expected a number from 0 to 1"), std::string::npos) << error;
    }
    EXPECT_EQ(v, 0.1);  // unchanged by the failures
}

}  // namespace
}  // namespace gridcull
