// The flight recorder (ui/flight_recorder.h): a key at once, then one per
// period of wall time at the observer's place, targets ahead along its view;
// nothing kept when not recording; stop keeps the keys, start drops them.
#include <gtest/gtest.h>

#include "ui/flight_recorder.h"

namespace gridcull {
namespace {

TEST(FlightRecorder, KeepsAKeyEveryPeriodFromTheStart) {
    FlightRecorder flight;
    flight.sample(1.0, 0.04, {0, 0, 0}, {0, 0, 1}, 5.0);
    EXPECT_TRUE(flight.keys().empty()) << "not recording";
    flight.start();
    flight.sample(0.0, 0.04, {1, 2, 3}, {1, 0, 0}, 5.0);
    ASSERT_EQ(flight.keys().size(), 1u);
    EXPECT_EQ(flight.keys()[0].t, 0.0);
    EXPECT_EQ(flight.keys()[0].target, glm::dvec3(6, 2, 3));
    flight.sample(0.03, 0.04, {2, 2, 3}, {1, 0, 0}, 5.0);
    EXPECT_EQ(flight.keys().size(), 1u);
    flight.sample(0.02, 0.04, {3, 2, 3}, {1, 0, 0}, 5.0);
    ASSERT_EQ(flight.keys().size(), 2u);
    EXPECT_DOUBLE_EQ(flight.keys()[1].t, 0.04);
    EXPECT_EQ(flight.keys()[1].position, glm::dvec3(3, 2, 3));
    // A slow frame: one key per period it spanned, times increasing.
    flight.sample(0.13, 0.04, {4, 2, 3}, {1, 0, 0}, 5.0);
    ASSERT_EQ(flight.keys().size(), 5u);
    EXPECT_DOUBLE_EQ(flight.seconds(), 0.16);
    flight.stop();
    flight.sample(1.0, 0.04, {9, 9, 9}, {1, 0, 0}, 5.0);
    EXPECT_EQ(flight.keys().size(), 5u) << "stopped";
    flight.start();
    EXPECT_TRUE(flight.keys().empty());
    flight.discard();
    EXPECT_FALSE(flight.recording());
}

}  // namespace
}  // namespace gridcull
