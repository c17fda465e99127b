// bench/memory.hpp: how much heap the process holds, the same count for every engine.
#pragma once

#include <cstddef>

namespace jostle::bench {

/// Bytes handed out by malloc and not yet freed, in the heap's arenas and in blocks it
/// mapped on its own (large arrays): glibc's mallinfo2() uordblks + hblkhd. The
/// difference of two readings is what was allocated in between, whatever allocated it
/// (new, malloc, calloc: C++ jostle, C++ Box2D and C Chipmunk alike).
std::size_t heapInUse();

} // namespace jostle::bench
