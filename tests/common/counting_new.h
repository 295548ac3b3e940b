// Counting allocations: this header replaces the global operator new and
// delete of the test binary that includes it, so include it from exactly one
// .cpp per binary. Between startCounting() and stopCounting()
// (tests/common/allocation_counter.h) every operator new adds one to
// allocationCount(); the tests of "hot per-frame paths do not allocate"
// measure with it.
#pragma once
#include <cstdlib>
#include <new>

#include "tests/common/allocation_counter.h"

// GCC 12 flags free() of operator new's memory once it inlines the pair; here
// both sides are ours and use malloc / free.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"


void* operator new(std::size_t size) {
    if (gridcull::test::g_counting.load(std::memory_order_relaxed))
        gridcull::test::g_allocations.fetch_add(1);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    return ::operator new(size);
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
// The nothrow forms too (std::stable_sort's temporary buffer uses them): left
// to the runtime, their memory would come back through our delete, a mismatch
// that AddressSanitizer reports.
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    if (gridcull::test::g_counting.load(std::memory_order_relaxed))
        gridcull::test::g_allocations.fetch_add(1);
    return std::malloc(size ? size : 1);
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
    return ::operator new(size, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
