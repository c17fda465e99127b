-- The example level through the installed module's jostle.loadTiled (the rock's levels):
-- its world has the map's bodies, and its spawn point is where Tiled put it (40, 200).
--   lua load_level.lua examples/levels/level.tmj
local jostle = require("jostle")
local path = assert(arg[1], "usage: load_level.lua LEVEL")
assert(jostle.loadTiled, "the module has no jostle.loadTiled")
local world, objects = jostle.loadTiled(path)
local spawn
for _, object in ipairs(objects) do
  if object.name == "spawn" then spawn = object end
end
assert(spawn and spawn.x == 40 and spawn.y == 200, "the spawn point is at (40, 200)")
assert(world:getBodyCount() > 0, "the level has bodies")
print(string.format("%s: %d bodies, %d objects, spawn at (%g, %g)", path, world:getBodyCount(),
  #objects, spawn.x, spawn.y))
