// The heap in use, for what a culler's copies (the checkpoints) and a trade
// setting's culler take: glibc's mallinfo2, bytes in the arenas and in chunks
// big enough to be mapped alone. A sanitized build's allocator reports its own
// figures, so measured sizes there are not the release build's.
#pragma once
#include <malloc.h>

#include <cstddef>

namespace gridcull {

inline size_t heapBytesInUse() {
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

}  // namespace gridcull
