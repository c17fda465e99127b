// Heap in use, from glibc's allocator statistics.
#include "memory.hpp"

#include <malloc.h>

namespace jostle::bench {

std::size_t heapInUse() {
    const struct mallinfo2 info = mallinfo2();
    return info.uordblks + info.hblkhd;
}

} // namespace jostle::bench
