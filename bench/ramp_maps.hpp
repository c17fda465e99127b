// bench/ramp_maps.hpp: big maps of ramp tiles created, changed and destroyed, timed
// (jostle alone: what a level of ramps costs to build and to edit, apart from stepping).
#pragma once

#include <cstdio>
#include <vector>

namespace jostle::bench {

/// For each size N: a map of N × N '/' tiles (one ramp body each) created in a new world;
/// setTile in its middle, '/' to '\\' and back; the map destroyed. Prints to `out` the
/// median wall-clock time of `runs` runs of each.
void runRampMaps(std::FILE* out, const std::vector<int>& sizes, int runs);

} // namespace jostle::bench
