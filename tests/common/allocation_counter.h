// The allocation counter's switch and count, without the replacement of
// operator new that feeds them (tests/common/counting_new.h). A test binary
// compiles counting_new.h into exactly one .cpp (core_tests:
// tests/culling/counting_new.cpp); every test that measures includes this.
#pragma once
#include <atomic>

namespace gridcull::test {

inline std::atomic<bool> g_counting{false};
inline std::atomic<long> g_allocations{0};

inline void startCounting() {
    g_allocations = 0;
    g_counting = true;
}
inline void stopCounting() {
    g_counting = false;
}
inline long allocationCount() {
    return g_allocations;
}

}  // namespace gridcull::test
