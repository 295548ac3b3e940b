// Seeds for randomized tests ("a --seed on every random test"). A test
// loops over seedsToRun(first, count); the environment variable GRIDCULL_SEED,
// when set, replaces those seeds by that one. withSeed() runs one seed's body
// and, if it failed, adds a failure that names the seed and the one command
// that replays it:
//   GRIDCULL_SEED=17 /path/to/core_tests --gtest_filter=Suite.Test
#pragma once
#include <unistd.h>
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace gridcull::test {

inline std::vector<uint64_t> seedsToRun(uint64_t first, int count) {
    if (const char* env = std::getenv("GRIDCULL_SEED")) {
        if (*env != '\0') return {std::strtoull(env, nullptr, 10)};
    }
    std::vector<uint64_t> seeds;
    for (int i = 0; i < count; ++i) seeds.push_back(first + uint64_t(i));
    return seeds;
}

// Sanitized builds run the long sweeps on a fifth of their scenes: the
// sanitizers look for memory and undefined-behaviour errors, which the first
// scenes already exercise on every code path, at about four times the cost per
// scene; the full build runs every scene and carries the false-cull counts.
#if defined(__SANITIZE_ADDRESS__)
constexpr int kSanitizedSweepDivisor = 5;
#else
constexpr int kSanitizedSweepDivisor = 1;
#endif

// The scene count of a long sweep: GRIDCULL_SWEEP_SCENES when set (a longer
// sweep by hand), else `full`, divided by kSanitizedSweepDivisor (at least 1).
inline int sweepScenes(int full) {
    if (const char* count = std::getenv("GRIDCULL_SWEEP_SCENES"))
        return std::max(1, std::atoi(count));
    return std::max(1, full / kSanitizedSweepDivisor);
}

// True when GRIDCULL_SEED picks one seed (tests that count over all their seeds
// skip such totals then).
inline bool singleSeedRun() {
    const char* env = std::getenv("GRIDCULL_SEED");
    return env && *env != '\0';
}

// The command that runs the current test again on `seed` alone.
inline std::string replayCommand(uint64_t seed) {
    char exe[4096];
    const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    const std::string path = n > 0 ? std::string(exe, size_t(n)) : std::string("core_tests");
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const std::string filter =
        info ? std::string(info->test_suite_name()) + "." + info->name() : std::string("*");
    return "GRIDCULL_SEED=" + std::to_string(seed) + " " + path + " --gtest_filter=" + filter;
}

template <class Body>
void withSeed(uint64_t seed, Body&& body) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const bool had_failure = ::testing::Test::HasFailure();
    body();
    if (!had_failure && ::testing::Test::HasFailure())
        ADD_FAILURE() << "seed " << seed << " failed; replay it with: " << replayCommand(seed);
}

}  // namespace gridcull::test
