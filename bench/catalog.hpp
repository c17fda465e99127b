// bench/catalog.hpp: which scenes the benchmark runs, at which sizes, for how many steps.
#pragma once

#include "jostle/scene.hpp"

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace jostle::bench {

/// One scene at one size, and how long to run it.
struct Case {
    std::string name;   ///< e.g. "rain_100k"
    std::string family; ///< e.g. "rain"
    int size = 0;       ///< the family's size parameter (rows, count, actors)
    std::function<Scene()> make;
    int warmup = 0; ///< steps before measuring: settle the scene, fill caches
    int steps = 0;  ///< steps measured
};

/// The scene families: pyramid, many_pyramids, rain, gas, tilemap; and, run only when
/// named, pile, a stress scene (--scene pile_10k), and long_floor and tiled_floor, a crowd
/// on one long floor and on a tiled one (--scene long_floor_10k,tiled_floor_10k).
const std::vector<std::string_view>& families();

/// The cases run by default (full sizes), or with --quick (small sizes, few steps).
std::vector<Case> defaultCases(bool quick);

/// The cases a --scene argument names: a family ("rain": its cases in defaultCases), a
/// case ("rain_100k"), or a family at any size ("rain_30k", "pyramid_50"; run for as many
/// steps as the family's first default case). Throws std::invalid_argument if it names
/// nothing.
std::vector<Case> selectCases(std::string_view name, bool quick);

/// One family at several sizes, for a plot of time against body count.
/// Throws std::invalid_argument for an unknown family.
std::vector<Case> seriesCases(std::string_view family, bool quick);

/// "1000" -> "1k", "100000" -> "100k", "20" -> "20".
std::string sizeLabel(int size);

} // namespace jostle::bench
