// A picture of the broadphase for debug drawing. The real grids are internal to the
// library (src/box_grid.hpp) and stay so: this works out, in the demo, the levels and
// cells that the rule of docs/broadphase.md gives for the bodies it can see through the
// public API. It mirrors the documented rule and is a picture, not the real structure:
// it is computed again from the bodies as they are when drawn, and the library's grown
// boxes use the velocity after the next step's gravity, which a picture cannot know.
#pragma once

#include "world_box.hpp"

#include "jostle/world.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace jostle::demo {

/// One box of the pictured grid, where the rule files it.
struct GridBox {
    WorldBox bounds; ///< the box as the grid holds it (grown by its motion if it moves)
    Vec2 growth;     ///< how much larger than its body, on each side
    int level = 0;   ///< from 0, the finest; kGridLevels - 1 is one infinite cell
};

/// The grid the library documents: 64 levels, the last one infinite.
constexpr int kGridLevels = 64;

struct GridPicture {
    /// Which of the world's grids (docs/broadphase.md, "How the world uses it"): while
    /// anything moves, the one rebuilt every step ("moving"; in the classic model, the
    /// grid of dynamic bodies, "dynamic"), else the one of what rests ("resting"; in the
    /// classic model "static").
    std::string name;
    std::vector<GridBox> boxes;
    double levelZero = 0.0; ///< cell size of level 0; level k's cells are 2^k times that
    int mainLevel = 0;      ///< the level holding the most boxes (the finer on a tie)
    std::size_t inMainLevel = 0;

    double cellSize(int level) const;
};

/// The picture of `world`'s grid as its last step would have built it, steps being `dt`
/// seconds long.
GridPicture pictureGrid(const World& world, float dt);

} // namespace jostle::demo
