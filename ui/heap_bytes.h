// The heap in use, for what a culler's copies (the checkpoints) and a trade
// setting's culler take: glibc's mallinfo2, bytes in the arenas and in chunks
// big enough to be mapped alone. Under AddressSanitizer glibc's arenas are not
// used (mallinfo2 reports nothing), so the sanitizer's own count of allocated
// bytes stands in; its figures are not the release build's.
#pragma once
#include <malloc.h>

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
// The sanitizer runtime's own count (its header does not ship with every compiler).
extern "C" size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace gridcull {

inline size_t heapBytesInUse() {
#if defined(__SANITIZE_ADDRESS__)
    return __sanitizer_get_current_allocated_bytes();
#else
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
#endif
}

}  // namespace gridcull
