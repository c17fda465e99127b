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
