-- Tile maps: solid tiles made into few static boxes that stop bodies, changed at run time.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

local rows = {
  "........",
  "#......#",
  "########",
}

-- Tiles of 16: row 2 (the floor) spans y = 32 to 48, so its top is y = 32.
local function scene()
  local world = jostle.newWorld({gravity = {0, 800}, sleeping = false})
  local map = world:newTileMap({x = 0, y = 0, tile = 16, rows = rows})
  return world, map
end

test("the map's tiles become few boxes: one per run, the floor one box", function()
  local world, map = scene()
  local bodies = map:getBodies()
  -- Row 1: two runs of one tile; row 2: one run of eight.
  t.equal(#bodies, 3, "boxes")
  t.equal(world:getBodyCount(), 3, "all the world's bodies")
  local hw, hh = bodies[3]:getHalfExtents()
  t.equal(hw, 64, "the floor's half width: 8 tiles of 16 / 2")
  t.equal(hh, 8, "half height")
  local x, y = bodies[3]:getPosition()
  t.equal(x, 64, "floor centre x")
  t.equal(y, 40, "floor centre y")
  t.equal(bodies[3]:getType(), "static", "static")
  t.truthy(bodies[1]:getTileMap() == map, "a box knows its map")
  t.equal(world:newBody({x = 0, y = -100, hw = 1, hh = 1}):getTileMap(), nil, "others have none")
end)

test("a box lands on the map, and falls when the tiles under it go", function()
  local world, map = scene()
  local box = world:newBody({x = 64, y = -20, hw = 4, hh = 4})
  t.steps(world, 90)
  local _, y = box:getPosition()
  t.near(y, 32 - 4, 0.01 * 4 + 1e-4, "resting on the floor's top")
  t.truthy(box:getTouching().floor, "touching the floor")
  -- The box spans x = 60 to 68: tiles 3 (48..64) and 4 (64..80) hold it.
  map:setTile(3, 2, false)
  map:setTile(4, 2, false)
  t.equal(#map:getBodies(), 4, "the floor split in two")
  t.steps(world, 30)
  _, y = box:getPosition()
  t.truthy(y > 48, "fell through the hole (y = " .. y .. ")")
  -- Filling the hole again makes one floor box again.
  map:setTile(3, 2, true)
  map:setTile(4, 2, true)
  t.equal(#map:getBodies(), 3, "merged again")
end)

test("isSolid, tileAt, getSize, getDef", function()
  local _, map = scene()
  t.equal(map:isSolid(0, 1), true, "(0, 1)")
  t.equal(map:isSolid(1, 1), false, "(1, 1)")
  t.equal(map:isSolid(-1, 0), false, "outside the map is empty")
  t.equal(map:isSolid(100, 100), false, "far outside")
  local column, row = map:tileAt(20, 40)
  t.equal(column, 1, "column of x = 20")
  t.equal(row, 2, "row of y = 40")
  -- On the edge between two tiles: the larger column and row.
  column, row = map:tileAt(16, 16)
  t.equal(column + row, 2, "edge (16, 16) is tile (1, 1)")
  t.equal(map:tileAt(-1, 0), nil, "outside: nil")
  t.equal(map:tileAt(128, 0), nil, "past the right edge: nil")
  local columns, rowCount = map:getSize()
  t.equal(columns, 8, "columns")
  t.equal(rowCount, 3, "rows")
  map:setTile(2, 0, true)
  local def = map:getDef()
  t.equal(def.tile, 16, "tile")
  t.equal(def.x + def.y, 0, "origin")
  t.equal(def.rows[1], "..#.....", "row 0 with the new tile")
  t.equal(def.rows[3], "########", "row 2")
  t.equal(def.friction, 0.5, "default friction")
  t.equal(def.sensor, false, "sensor")
end)

-- Ramp tiles, tiles of 16 at the origin:
--   row 0  ........
--   row 1  ./....rR
--   row 2  ########   (top at y = 32)
-- The "/" at (1, 1) covers x 16..32, y 16..32 and keeps the triangle under the line from
-- (16, 32) to (32, 16): x + y = 48, its normal (-1, -1) / sqrt(2). "rR" is one 2:1 ramp
-- over x 96..128.
local k = math.sqrt(0.5)

-- A ray straight down at x meets the map at y with the normal (nx, ny).
local function hitsDownAt(world, x, y, nx, ny, what)
  local body, hx, hy, hnx, hny = world:rayCast(x, 0, x, 100)
  t.truthy(body, what .. ": a hit")
  t.near(hx, x, 1e-4, what .. ": x")
  t.near(hy, y, 1e-4, what .. ": y")
  t.near(hnx, nx, 1e-6, what .. ": nx")
  t.near(hny, ny, 1e-6, what .. ": ny")
end

test("ramp tiles: in the rows, read back by tileOf and getDef, set by character", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local map = world:newTileMap({tile = 16, rows = {"........", "./....rR", "########"}})
  local bodies = map:getBodies()
  t.equal(#bodies, 3, "the floor, then the two ramps")
  local x, y = bodies[2]:getPosition()
  local hw, hh = bodies[2]:getHalfExtents()
  t.equal(x + y + hw + hh, 24 + 24 + 8 + 8, "the '/' fills tile (1, 1)")
  local slope = bodies[2]:getDef().slope
  t.equal(slope[1] + slope[2], -2, "a floor rising to the right: slope {-1, -1}")
  x, y = bodies[3]:getPosition()
  hw, hh = bodies[3]:getHalfExtents()
  t.equal(x, 112, "'rR' centre x")
  t.equal(y, 24, "'rR' centre y")
  t.equal(hw, 16, "'rR' is two tiles wide")
  t.equal(hh, 8, "and one tall")
  t.equal(map:tileOf(1, 1), "/", "(1, 1)")
  t.equal(map:tileOf(6, 1) .. map:tileOf(7, 1), "rR", "(6, 1) and (7, 1)")
  t.equal(map:tileOf(0, 2), "#", "(0, 2)")
  t.equal(map:tileOf(-1, 0) .. map:tileOf(8, 2), "..", "outside: empty")
  t.equal(map:isSolid(1, 1), false, "a ramp is not a solid tile")
  hitsDownAt(world, 28, 48 - 28, -k, -k, "the slope of '/' at x = 28")

  -- A "\" at (2, 1): x 32..48, y 16..32, solid under the line y = x - 16, normal (1, -1) / sqrt(2).
  map:setTile(2, 1, "\\")
  t.equal(map:tileOf(2, 1), "\\", "set by its character")
  t.equal(#map:getBodies(), 4, "one more body")
  hitsDownAt(world, 36, 36 - 16, k, -k, "the slope of '\\' at x = 36")
  t.equal(map:getDef().rows[2], "./\\...rR", "getDef's rows carry the ramps")
  map:setTile(2, 1, false)
  hitsDownAt(world, 36, 32, 0, -1, "emptied: the floor at x = 36")
  map:setTile(1, 1, true)
  t.equal(map:tileOf(1, 1), "#", "a ramp made solid")
  hitsDownAt(world, 28, 16, 0, -1, "the solid tile's top at x = 28")
  map:setTile(1, 1, ".")
  t.equal(map:tileOf(1, 1), ".", "emptied by its character")
  t.equal(#map:getBodies(), 2, "the floor and 'rR'")

  -- A map made from getDef has the same tiles.
  local copy = world:newTileMap(map:getDef())
  t.equal(table.concat(copy:getDef().rows, "|"), "........|......rR|########", "the copy")
end)

test("a ball rolls down a ramp tile onto the floor", function()
  -- The '/' at (7, 1) covers x 112..128, y 16..32 under the line x + y = 144. A
  -- frictionless ball of radius 4 starts at rest touching it at (120, 24), its centre 4
  -- along the normal (-1, -1) / sqrt(2) from there. It slides down to the foot at
  -- (112, 32) in about 0.2 s and rolls left along the floor, its centre 4 above it.
  local world = jostle.newWorld({gravity = {0, 800}})
  world:newTileMap({tile = 16, rows = {"........", "......./", "########"}, friction = 0})
  local ball = world:newBody({x = 120 - 4 * k, y = 24 - 4 * k, hw = 4, hh = 4, radius = 4,
    friction = 0})
  t.steps(world, 30)
  local x, y = ball:getPosition()
  t.truthy(x < 112, "left the ramp's foot (x = " .. x .. ")")
  t.near(y, 32 - 4, 0.05, "on the floor")
  local vx = ball:getVelocity()
  t.truthy(vx < 0, "rolling left")
end)

test("a sensor map reports what enters it and stops nothing", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local water = world:newTileMap({x = -32, y = 0, tile = 16, rows = {"####", "####"}, sensor = true})
  local box = world:newBody({x = 0, y = -20, hw = 4, hh = 4})
  local entered
  for _ = 1, 60 do
    world:step(1 / 60)
    for _, e in ipairs(world:getSensorBegins()) do
      if e.visitor == box then entered = e.sensor end
    end
  end
  t.truthy(entered and entered:getTileMap() == water, "entered the water map")
  local _, y = box:getPosition()
  t.truthy(y > 32, "fell through it")
end)

test("a one-way map holds from above only", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  world:newTileMap({x = -32, y = 0, tile = 16, rows = {"####"}, oneWay = {0, -1}})
  local faller = world:newBody({x = -8, y = -20, hw = 4, hh = 4})
  local jumper = world:newBody({x = 8, y = 40, hw = 4, hh = 4, vy = -500})
  -- The jumper rises v^2 / 2g = 156 above its start, then falls back: 1.2 s in all.
  t.steps(world, 90)
  t.near(select(2, faller:getPosition()), -4, 0.05, "the faller stands on it")
  -- The jumper passed up through it (its bottom went above y = 0) and landed on top.
  t.near(select(2, jumper:getPosition()), -4, 0.05, "the jumper came through and landed")
end)

test("destroying the map destroys its boxes", function()
  local world, map = scene()
  local first = map:getBodies()[1]
  map:destroy()
  t.equal(map:isDestroyed(), true, "map destroyed")
  t.equal(first:isDestroyed(), true, "its box destroyed")
  t.equal(world:getBodyCount(), 0, "no bodies left")
  t.truthy(map:getWorld() == world, "getWorld still answers")
end)

return t.run(tests)
