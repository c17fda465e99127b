// Drops a box on a floor through the installed package; exits 0 if it landed.
#include <jostle/world.hpp>

#include <cstdio>

int main() {
    jostle::WorldDef def;
    def.gravity = {0, 800};
    jostle::World world(def);
    world.createBody({.type = jostle::BodyType::Static, .x = 0, .y = 100, .hw = 100, .hh = 10});
    jostle::BodyId box = world.createBody({.x = 0, .y = 0, .hw = 10, .hh = 10});
    for (int i = 0; i < 120; ++i)
        world.step(1.0f / 60.0f);
    // The floor's top is at y = 90, so the resting box's centre is at 80.
    float y = world.position(box).y;
    std::printf("box at y = %g\n", static_cast<double>(y));
    return (y > 79.0f && y < 81.0f) ? 0 : 1;
}
