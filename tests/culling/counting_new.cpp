// core_tests' one replacement of operator new and delete
// (tests/common/counting_new.h), which feeds the allocation counter that the
// "hot per-frame paths do not allocate" tests of every module read through
// tests/common/allocation_counter.h.
#include <vector>

#include <gtest/gtest.h>

#include "tests/common/counting_new.h"

namespace gridcull {
namespace {

TEST(AllocationCounter, SeesAnAllocation) {
    test::startCounting();
    auto* v = new std::vector<int>(10);
    test::stopCounting();
    delete v;
    EXPECT_EQ(test::allocationCount(), 2);  // the vector and its buffer
}

}  // namespace
}  // namespace gridcull
