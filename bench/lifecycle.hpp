// bench/lifecycle.hpp: creating and destroying many bodies, timed (jostle alone: what a
// game pays to fill a level and empty it, apart from stepping).
#pragma once

#include <cstdio>

namespace jostle::bench {

/// Creates `count` bodies in a new world and destroys them all in creation order, then
/// creates them again and destroys them all in reverse order, and prints to `out` the
/// wall-clock seconds of each of the four.
void runLifecycle(std::FILE* out, int count);

} // namespace jostle::bench
