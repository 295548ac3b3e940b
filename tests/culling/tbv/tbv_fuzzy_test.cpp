// Fuzzy TBVs (Sudarsky & Gotsman section 3.5) and the experiment of Fig. 14
// (a fraction of the valid TBVs invalidated each frame), through TbvManager
// (culling/tbv/tbv_manager.h).
#include <cmath>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "culling/tbv/tbv_manager.h"
#include "tests/culling/tbv/tbv_toy_world.h"

namespace gridcull {
namespace {

// The box of the toy's disc of radius 0.5 at (x, 0).
TbvBox toyBox(double x) {
    return test::toyDisc(glm::dvec3(x, 0.0, 0.0), 0.5);
}

TbvShape discTbv(double x, double validity) {
    return sphereTbv(2, glm::dvec3(x, 0.0, 0.0), 0.5, 1.0, validity);
}

// The object's controller finds it outside its TBV and reports it: the TBV is
// dropped in step 1 of that very frame (state Violated, the object back in V,
// its period untouched), before anything else reads it.
TEST(TbvFuzzy, ReportedViolationDropsTheTbvInTheSameFrame) {
    TbvManagerOptions o;
    o.validity_mode = TbvValidityMode::Adaptive;
    o.initial_validity = 10.0;
    TbvManager m;
    m.reset(2, o);
    m.addDynamic(0);
    m.addDynamic(1);
    m.beginFrame(0.0, [](int, TbvDropReason) { FAIL() << "nothing to drop"; });
    for (const int id : m.objectsToUpdate()) m.updVis(id);
    m.endFrame([](int id, double& validity) { return discTbv(id == 0 ? -50.0 : -80.0, validity); });
    ASSERT_TRUE(m.hasTbv(0));
    // The TBV is the disc of radius 0.5 + 1 * 10 around x = -50.
    EXPECT_FALSE(m.violates(0, glm::dvec3(-45.0, 0.0, 0.0), 0.5));
    EXPECT_FALSE(m.violates(0, toyBox(-40.5)));
    EXPECT_TRUE(m.violates(0, glm::dvec3(5.0, 0.0, 0.0), 0.5));
    EXPECT_TRUE(m.violates(0, toyBox(-39.0)));
    EXPECT_TRUE(m.reportViolation(0));
    EXPECT_TRUE(m.reportViolation(0));  // twice: one report
    EXPECT_TRUE(m.hasTbv(0));           // not before the frame's step 1

    std::vector<std::pair<int, TbvDropReason>> dropped;
    m.beginFrame(1.0, [&](int id, TbvDropReason why) { dropped.push_back({id, why}); });
    ASSERT_EQ(dropped.size(), 1u);
    EXPECT_EQ(dropped[0].first, 0);
    EXPECT_EQ(dropped[0].second, TbvDropReason::Violated);
    EXPECT_EQ(m.state(0), TbvObjectState::Violated);
    EXPECT_FALSE(m.hasTbv(0));
    EXPECT_TRUE(m.inV(0));
    EXPECT_FALSE(m.queue().scheduled(0));
    EXPECT_TRUE(m.hasTbv(1));
    EXPECT_DOUBLE_EQ(m.period(0), 10.0);  // neither doubled nor halved
    EXPECT_EQ(m.frameCounters().tbv_violated, 1);
    EXPECT_EQ(m.frameCounters().violation_messages, 1);
    // TBVe: step 2 rewrites it at once.
    ASSERT_EQ(m.objectsToUpdate().size(), 1u);
    EXPECT_EQ(m.objectsToUpdate()[0], 0);
    m.updVis(0);
    m.observe(0);
    m.endFrame([](int, double&) -> TbvShape {
        ADD_FAILURE() << "observed: no TBV";
        return {};
    });
    EXPECT_EQ(m.state(0), TbvObjectState::Visible);
    EXPECT_FALSE(m.reportViolation(0));  // no TBV, nothing to violate
}

// In the toy world: an object behind the wall, declared at speed 1, jumps into
// view at t = 2.5. Reported, it is shown at t = 3, the first frame it is in
// view; unreported, its hidden TBV keeps it out of sight until it expires.
TEST(TbvFuzzy, ReportedJumpIsShownInTheFrameItHappens) {
    const test::ToyObject jumper{
        [](double t) { return glm::dvec3(t < 2.5 ? -50.0 : 5.0, 0.0, 0.0); }, 0.5, 1.0};
    TbvManagerOptions o;
    o.validity_mode = TbvValidityMode::Fixed;
    o.initial_validity = 10.0;
    for (const bool report : {true, false}) {
        test::ToyTbvCuller toy({jumper}, o);
        toy.report_violations = report;
        std::vector<double> shown_at;
        for (int f = 0; f <= 12; ++f)
            if (!toy.frame(double(f)).shown.empty()) shown_at.push_back(double(f));
        ASSERT_FALSE(shown_at.empty());
        // Unreported: the TBV made at t = 0 lasts to 10, expires at t = 11.
        EXPECT_EQ(shown_at.front(), report ? 3.0 : 11.0) << (report ? "reported" : "unreported");
    }
}

// A report about a TBV that ends before the next step 1 (revealed in the same
// frame) does not drop the object's next TBV.
TEST(TbvFuzzy, ReportOutlivedByItsTbvDoesNotDropTheNextOne) {
    TbvManagerOptions o;
    o.validity_mode = TbvValidityMode::Fixed;
    o.initial_validity = 10.0;
    TbvManager m;
    m.reset(1, o);
    m.addDynamic(0);
    m.beginFrame(0.0, [](int, TbvDropReason) {});
    m.updVis(0);
    m.endFrame([](int, double& v) { return discTbv(-50.0, v); });
    m.beginFrame(1.0, [](int, TbvDropReason) {});
    EXPECT_TRUE(m.reportViolation(0));  // mid-frame: for the next step 1
    EXPECT_TRUE(m.reveal(0));
    EXPECT_FALSE(m.reveal(0));  // met again at another node: already done
    m.endFrame([](int, double& v) { return discTbv(-50.0, v); });  // TBV number 2
    ASSERT_TRUE(m.hasTbv(0));
    m.beginFrame(2.0, [](int, TbvDropReason why) {
        EXPECT_NE(why, TbvDropReason::Violated) << "the report was about the previous TBV";
    });
    EXPECT_TRUE(m.hasTbv(0));
    EXPECT_EQ(m.frameCounters().violation_messages, 1);  // the report was still sent
    EXPECT_EQ(m.frameCounters().tbv_violated, 0);
}

// Fig. 14's experiment: each frame, invalidate_fraction of the valid TBVs are
// dropped at random. 1000 objects behind the wall under TBVs that never expire;
// each frame the dropped ones get new TBVs, so 1000 are valid at every step 1.
struct InvalidationRun {
    std::vector<std::pair<int, int>> picks;  // (frame, object)
    std::vector<size_t> valid;               // valid TBVs at each frame's step 1
    std::vector<size_t> dropped;             // invalidated in each frame
};

InvalidationRun runInvalidation(double fraction, uint64_t seed, int objects, int frames) {
    std::vector<test::ToyObject> all;
    for (int i = 0; i < objects; ++i) all.push_back(test::toyStill(-1e6 - i));
    TbvManagerOptions o;
    o.validity_mode = TbvValidityMode::Fixed;
    o.initial_validity = 1e9;
    o.invalidate_fraction = fraction;
    o.seed = seed;
    test::ToyTbvCuller toy(all, o);
    InvalidationRun run;
    for (int f = 0; f < frames; ++f) {
        run.valid.push_back(toy.manager().hiddenObjects().size());
        const test::ToyFrame frame = toy.frame(double(f));
        size_t k = 0;
        for (const auto& d : frame.dropped) {
            EXPECT_EQ(d.second, TbvDropReason::Invalidated);
            run.picks.push_back({f, d.first});
            ++k;
        }
        EXPECT_EQ(int64_t(k), frame.counters.tbv_invalidated);
        EXPECT_EQ(frame.counters.violation_messages, 0);  // a simulation knob, not a message
        run.dropped.push_back(k);
    }
    return run;
}

TEST(TbvFuzzy, InvalidatesTheFractionOfValidTbvsDeterministically) {
    const double kFraction = 0.1234;
    const int kObjects = 1000;
    const int kFrames = 400;
    const InvalidationRun run = runInvalidation(kFraction, 42, kObjects, kFrames);
    // Each frame: fraction * valid rounded down or up (up with the probability
    // of its fractional part), never anything else.
    size_t total_valid = 0, total_dropped = 0;
    for (int f = 0; f < kFrames; ++f) {
        const double expected = kFraction * double(run.valid[size_t(f)]);
        EXPECT_GE(double(run.dropped[size_t(f)]), std::floor(expected)) << "frame " << f;
        EXPECT_LE(double(run.dropped[size_t(f)]), std::ceil(expected)) << "frame " << f;
        total_valid += run.valid[size_t(f)];
        total_dropped += run.dropped[size_t(f)];
    }
    // Over the run the fraction is exact on average. The only randomness in the
    // count is the rounding: fraction * 1000 = 123.4 is rounded up with
    // probability p = 0.4 each frame, so the total's standard deviation is
    // sqrt(frames * p * (1 - p)) objects. Tolerance: 5 of those, as a fraction.
    const double p = kFraction * kObjects - std::floor(kFraction * kObjects);
    const double kMeanTolerance =
        5.0 * std::sqrt(double(kFrames) * p * (1.0 - p)) / double(total_valid);
    EXPECT_NEAR(double(total_dropped) / double(total_valid), kFraction, kMeanTolerance);
    // Uniform over the TBVs: each object's count is about Binomial(frames,
    // fraction) (frame 0 has no TBVs yet); none more than 6 standard
    // deviations from its mean (a chance below 1e-6 over 1000 objects).
    std::vector<int> per_object(kObjects, 0);
    for (const auto& pick : run.picks) ++per_object[size_t(pick.second)];
    const double mean = kFraction * (kFrames - 1);
    const double kSixSigma = 6.0 * std::sqrt(mean * (1.0 - kFraction));
    for (int i = 0; i < kObjects; ++i)
        ASSERT_NEAR(per_object[size_t(i)], mean, kSixSigma) << "object " << i;
    // Deterministic: the same seed picks the same TBVs, another seed others.
    EXPECT_EQ(runInvalidation(kFraction, 42, kObjects, kFrames).picks, run.picks);
    EXPECT_NE(runInvalidation(kFraction, 43, kObjects, kFrames).picks, run.picks);
    // Fraction 0 drops none, fraction 1 all.
    EXPECT_EQ(runInvalidation(0.0, 42, 50, 5).picks.size(), 0u);
    EXPECT_EQ(runInvalidation(1.0, 42, 50, 5).picks.size(), 4u * 50u);
}

}  // namespace
}  // namespace gridcull
