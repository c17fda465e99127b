-- Misuse: every mistake is a Lua error with a message that names the method, the
-- argument or field, and the rule; never a crash, and the world stays usable.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

local function newWorld()
  local world = jostle.newWorld({gravity = {0, 800}})
  local floor = world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
  local box = world:newBody({x = 0, y = 0, hw = 10, hh = 10})
  return world, floor, box
end

test("a destroyed body's methods raise, except the ones that ask about it", function()
  local world, _, box = newWorld()
  box:destroy()
  t.equal(box:isDestroyed(), true, "isDestroyed")
  t.truthy(box:getWorld() == world, "getWorld still answers")
  t.truthy(select("#", box:getId()) == 3, "getId still answers")
  t.truthy(tostring(box):find("destroyed", 1, true), "tostring says destroyed")
  local harmless = {isDestroyed = true, getWorld = true, getId = true}
  local methods = getmetatable(box).__index
  local count = 0
  for name, method in pairs(methods) do
    if not harmless[name] then
      -- Arguments that would be valid for a live body, so that only "destroyed" is wrong.
      t.raises({"Body:" .. name, "the body was destroyed"}, method, box, 1, 1)
      count = count + 1
    end
  end
  t.truthy(count >= 40, "checked every method (" .. count .. ")")
  -- The world goes on.
  world:step(1 / 60)
  t.equal(world:getBodyCount(), 1, "count")
end)

test("destroying twice, and using a body as another world's argument", function()
  local world, _, box = newWorld()
  local other = jostle.newWorld()
  t.raises({"World:queryPoint", "filter.ignore", "another world"},
    other.queryPoint, other, 0, 0, {ignore = box})
  box:destroy()
  t.raises({"Body:destroy", "the body was destroyed"}, box.destroy, box)
  t.raises({"World:rayCast", "filter.ignore", "the body was destroyed"},
    world.rayCast, world, 0, 0, 1, 1, {ignore = box})
end)

test("methods called with a dot instead of a colon", function()
  local world, _, box = newWorld()
  t.raises({"Body:getPosition", "expected a Body as self", "got no value"}, box.getPosition)
  t.raises({"Body:setPosition", "expected a Body as self", "got number"}, box.setPosition, 1, 2)
  t.raises({"World:step", "expected a World as self", "got number"}, world.step, 1 / 60)
  t.raises({"World:newBody", "expected a World as self", "got Body"}, world.newBody, box, {})
end)

test("wrong types, NaN and infinity in arguments", function()
  local world, _, box = newWorld()
  t.raises({"Body:setPosition", "x: expected a number, got string"}, box.setPosition, box, "1", 2)
  t.raises({"Body:setPosition", "y: expected a number, got no value"}, box.setPosition, box, 1)
  t.raises({"Body:setPosition", "x: must be a finite number"}, box.setPosition, box, 0 / 0, 0)
  t.raises({"Body:setVelocity", "vy: must be a finite number"}, box.setVelocity, box, 0, math.huge)
  -- Beyond float's range is infinite for the core: refused too.
  t.raises({"Body:setPosition", "x: must be a finite number"}, box.setPosition, box, 1e39, 0)
  t.raises({"World:setGravity", "y: expected a number, got table"}, world.setGravity, world, 0, {})
  t.raises({"Body:setBullet", "bullet: expected true or false, got number"}, box.setBullet, box, 1)
  t.raises({"Body:setType", 'type: expected one of "static", "kinematic", "dynamic", got "dynamc"'},
    box.setType, box, "dynamc")
  t.raises({"Body:setCategory", "category: expected a whole number"}, box.setCategory, box, 1.5)
  t.raises({"Body:setMask", "mask: must be from 0 to 4294967295"}, box.setMask, box, -1)
  t.raises({"Body:setMask", "mask: must be from 0 to 4294967295"}, box.setMask, box, 2 ^ 32)
  -- The body was not changed by any of these.
  local x, y = box:getPosition()
  t.equal(x + y, 0, "position unchanged")
end)

test("values out of range: the core's rules, named by the Lua method", function()
  local _, floor, box = newWorld()
  t.raises({"Body:setHalfExtents", "hw: must be > 0"}, box.setHalfExtents, box, 0, 1)
  t.raises({"Body:setHalfExtents", "hh: must be > 0"}, box.setHalfExtents, box, 1, -1)
  t.raises({"Body:setBounce", "bounce must be in [0, 1]"}, box.setBounce, box, 1.5)
  t.raises({"Body:setFriction", "friction must be in [0, 1]"}, box.setFriction, box, -0.1)
  t.raises({"Body:setMass", "mass must be > 0"}, box.setMass, box, 0)
  t.raises({"Body:setDensity", "density must be > 0"}, box.setDensity, box, 0)
  t.raises({"Body:setDamping", "damping must be >= 0"}, box.setDamping, box, -1)
  t.raises({"Body:setOneWay", "normal must be {0, 0} or one of"}, box.setOneWay, box, 1, 1)
  t.raises({"Body:dropThrough", "seconds must be a finite number >= 0"}, box.dropThrough, box, -1)
  -- Only a dynamic body falls onto one-way platforms, so only it drops through them.
  local only = "only a dynamic body drops through one-way platforms"
  t.raises({"Body:dropThrough", only}, floor.dropThrough, floor, 0.5)
  local lift = floor:getWorld():newBody({type = "kinematic", x = 0, y = 100, hw = 20, hh = 5})
  t.raises({"Body:dropThrough", only}, lift.dropThrough, lift, 0.5)
  t.raises({"Body:setVelocity", "a static body cannot move"}, floor.setVelocity, floor, 1, 0)
end)

test("dt <= 0, NaN or not a number", function()
  local world = newWorld()
  t.raises({"World:step", "dt: must be > 0"}, world.step, world, 0)
  t.raises({"World:step", "dt: must be > 0"}, world.step, world, -1 / 60)
  t.raises({"World:step", "dt: must be a finite number"}, world.step, world, 0 / 0)
  t.raises({"World:step", "dt: must be a finite number"}, world.step, world, math.huge)
  t.raises({"World:step", "dt: expected a number, got string"}, world.step, world, "1/60")
  t.raises({"World:step", "dt: expected a number, got no value"}, world.step, world)
  world:step(1 / 60)
end)

test("body definitions: the rules of scene files", function()
  local world = newWorld()
  local function newBody(def) return world:newBody(def) end
  t.raises({"World:newBody", "def: expected a table, got string"}, newBody, "box")
  t.raises({"World:newBody", "def: expected a table, got nil"}, newBody, nil)
  t.raises({"World:newBody", "hw: must be > 0"}, newBody, {hw = 0, hh = 1})
  t.raises({"World:newBody", "hh: must be > 0"}, newBody, {hw = 1, hh = -2})
  t.raises({"World:newBody", 'missing field "hw"'}, newBody, {hh = 1})
  t.raises({"World:newBody", 'missing field "hh"'}, newBody, {hw = 1})
  t.raises({"World:newBody", "hw: expected a number, got string"}, newBody, {hw = "10", hh = 1})
  t.raises({"World:newBody", "x: must be a finite number"}, newBody, {x = 0 / 0, hw = 1, hh = 1})
  t.raises({"World:newBody", "y: must be a finite number"}, newBody, {y = -math.huge, hw = 1, hh = 1})
  t.raises({"World:newBody", 'unknown field "frcition"'}, newBody, {hw = 1, hh = 1, frcition = 0.5})
  t.raises({"World:newBody", "unknown field [1]", "by name"}, newBody, {0, 0, 10, 10})
  t.raises({"World:newBody", 'type: expected one of "static", "kinematic", "dynamic", got "box"'},
    newBody, {type = "box", hw = 1, hh = 1})
  t.raises({"World:newBody", 'type: expected one of "static", "kinematic", "dynamic", got number'},
    newBody, {type = 1, hw = 1, hh = 1})
  t.raises({"World:newBody", "bounce: must be in [0, 1]"}, newBody, {hw = 1, hh = 1, bounce = 2})
  t.raises({"World:newBody", "mass: must be > 0"}, newBody, {hw = 1, hh = 1, mass = 0})
  t.raises({"World:newBody", 'give "mass" or "density", not both'},
    newBody, {hw = 1, hh = 1, mass = 1, density = 1})
  t.raises({"World:newBody", "oneWay: expected an array of 2 numbers"},
    newBody, {hw = 1, hh = 1, oneWay = "up"})
  t.raises({"World:newBody", "oneWay[2]: expected a number, got string"},
    newBody, {hw = 1, hh = 1, oneWay = {0, "up"}})
  t.raises({"World:newBody", "oneWay"}, newBody, {hw = 1, hh = 1, oneWay = {1, 1}})
  t.raises({"World:newBody", "category: must be from 0 to 4294967295"},
    newBody, {hw = 1, hh = 1, category = 2 ^ 40})
  t.raises({"World:newBody", "sensor: expected true or false, got string"},
    newBody, {hw = 1, hh = 1, sensor = "yes"})
  t.raises({"World:newBody", "vx: a static body cannot move"},
    newBody, {type = "static", hw = 1, hh = 1, vx = 5})
  t.equal(world:getBodyCount(), 2, "nothing was created")
end)

test("world definitions", function()
  local function newWorld_(def) return jostle.newWorld(def) end
  t.raises({"jostle.newWorld", "def: expected a table, got number"}, newWorld_, 800)
  t.raises({"jostle.newWorld", 'unknown field "gravty"'}, newWorld_, {gravty = {0, 800}})
  t.raises({"jostle.newWorld", "gravity: expected an array of 2 numbers, got number"},
    newWorld_, {gravity = 800})
  t.raises({"jostle.newWorld", "gravity[1]: must be a finite number"}, newWorld_, {gravity = {0 / 0, 1}})
  t.raises({"jostle.newWorld", "maxVelocity: must be > 0"}, newWorld_, {maxVelocity = 0})
  t.raises({"jostle.newWorld", 'solver: expected one of "classic", "physical"'},
    newWorld_, {solver = "box2d"})
  t.raises({"jostle.newWorld", 'classic: unknown field "mas"'}, newWorld_, {classic = {mas = true}})
  t.raises({"jostle.newWorld", "classic.mass: expected true or false, got number"},
    newWorld_, {classic = {mass = 1}})
  t.raises({"jostle.newWorld", "physical.velocityIterations: must be from 1 to 1000"},
    newWorld_, {physical = {velocityIterations = 0}})
  t.raises({"jostle.newWorld", "physical.velocityIterations: expected a whole number"},
    newWorld_, {physical = {velocityIterations = 2.5}})
  t.raises({"jostle.newWorld", "physical.slop"}, newWorld_, {physical = {slop = 0.9}})
  t.raises({"jostle.newWorld", 'physical.frictionMix: expected one of "min", "geometricMean", got "max"'},
    newWorld_, {physical = {frictionMix = "max"}})
  t.raises({"jostle.newWorld", "physical: expected a table, got boolean"}, newWorld_, {physical = true})
  local world = jostle.newWorld()
  t.raises({"World:setSolver", "solver: expected one of"}, world.setSolver, world, "exact")
  t.raises({"World:setMaxVelocity", "maxVelocity: must be > 0"}, world.setMaxVelocity, world, -1)
  t.raises({"World:setPhysicalOptions", "slop"}, world.setPhysicalOptions, world, {slop = -1})
  t.raises({"World:setPhysicalOptions", 'unknown field "slope"'},
    world.setPhysicalOptions, world, {slope = 0.1})
  t.raises({"World:setClassicOptions", "options: expected a table, got no value"},
    world.setClassicOptions, world)
end)

test("query arguments and filters", function()
  local world, _, box = newWorld()
  t.raises({"World:queryPoint", "y: expected a number, got no value"}, world.queryPoint, world, 0)
  t.raises({"World:queryBox", "hw: must be >= 0"}, world.queryBox, world, 0, 0, -1, 1)
  t.raises({"World:queryRect", "x1, y1 must be <= x2, y2"}, world.queryRect, world, 5, 0, 0, 5)
  t.raises({"World:boxCast", "hh: must be > 0"}, world.boxCast, world, 0, 0, 1, 0, 1, 1)
  t.raises({"World:moveAndSlide", "dx: must be a finite number"},
    world.moveAndSlide, world, 0, 0, 1, 1, 0 / 0, 0)
  t.raises({"World:rayCast", "filter: expected a table, got string"},
    world.rayCast, world, 0, 0, 1, 1, "level")
  t.raises({"World:rayCast", 'filter: unknown field "maks"'}, world.rayCast, world, 0, 0, 1, 1, {maks = 1})
  t.raises({"World:rayCast", "filter.mask: expected a whole number, got string"},
    world.rayCast, world, 0, 0, 1, 1, {mask = "all"})
  t.raises({"World:rayCast", "filter.ignore: expected a Body, got World"},
    world.rayCast, world, 0, 0, 1, 1, {ignore = world})
  t.raises({"World:queryPoint", "filter.includeSensors: expected true or false"},
    world.queryPoint, world, 0, 0, {includeSensors = 1})
  t.equal(#world:queryPoint(0, 0, {ignore = box}), 0, "a valid filter still works")
end)

test("tile map definitions and coordinates", function()
  local world = newWorld()
  local function newTileMap(def) return world:newTileMap(def) end
  t.raises({"World:newTileMap", 'missing field "tile"'}, newTileMap, {rows = {"#"}})
  t.raises({"World:newTileMap", 'missing field "rows"'}, newTileMap, {tile = 16})
  t.raises({"World:newTileMap", "tile: must be > 0"}, newTileMap, {tile = 0, rows = {"#"}})
  t.raises({"World:newTileMap", "rows: must have at least one row"}, newTileMap, {tile = 16, rows = {}})
  t.raises({"World:newTileMap", "rows: expected an array of strings, got string"},
    newTileMap, {tile = 16, rows = "#"})
  t.raises({"World:newTileMap", "rows[1]: must have at least one column"}, newTileMap, {tile = 16, rows = {""}})
  t.raises({"World:newTileMap", "rows[2]: has 3 columns, rows[1] has 4"},
    newTileMap, {tile = 16, rows = {"#..#", "###"}})
  t.raises({"World:newTileMap", "rows[2][3]: expected '#', '.' or a ramp, got 'x' (tile column 2, row 1)"},
    newTileMap, {tile = 16, rows = {"....", "##x#"}})
  t.raises({"World:newTileMap", "rows[1][1]: expected '#', '.' or a ramp, got byte 0x09"},
    newTileMap, {tile = 16, rows = {"\t"}})
  t.raises({"World:newTileMap", "rows[2]: expected a string, got number"}, newTileMap, {tile = 16, rows = {"#", 1}})
  t.raises({"World:newTileMap", 'unknown field "tileWidth"'}, newTileMap, {tileWidth = 16, rows = {"#"}})
  t.raises({"World:newTileMap", "friction"}, newTileMap, {tile = 16, rows = {"#"}, friction = 3})
  t.raises({"World:newTileMap", "x: must be a finite number"}, newTileMap, {tile = 16, rows = {"#"}, x = 0 / 0})
  local map = world:newTileMap({tile = 16, rows = {"##"}})
  t.raises({"TileMap:setTile", "outside the map"}, map.setTile, map, 2, 0, true)
  t.raises({"TileMap:setTile", "tile: expected true, false or a tile's character, got no value"},
    map.setTile, map, 0, 0)
  t.raises({"TileMap:setTile", "tile: expected one character, got a string of 2"},
    map.setTile, map, 0, 0, "##")
  t.raises({"TileMap:setTile", "expected '#', '.' or a ramp, got 'x'"}, map.setTile, map, 0, 0, "x")
  t.equal(map:tileOf(0, 0), "#", "left as it was")
  t.raises({"TileMap:tileOf", "row: expected a whole number, got string"}, map.tileOf, map, 0, "0")
  t.raises({"TileMap:setTile", "column: expected a whole number"}, map.setTile, map, 0.5, 0, true)
  t.raises({"TileMap:isSolid", "row: expected a whole number, got string"}, map.isSolid, map, 0, "0")
  map:destroy()
  t.raises({"TileMap:setTile", "the map was destroyed"}, map.setTile, map, 0, 0, true)
  t.raises({"TileMap:tileOf", "the map was destroyed"}, map.tileOf, map, 0, 0)
  t.equal(map:isDestroyed(), true, "isDestroyed")
end)

test("the classic model takes no ramp tiles", function()
  local world = jostle.newWorld({solver = "classic"})
  t.raises({"World:newTileMap",
    "rows[1][2]: the classic model has sharp boxes only: no ramps (tile column 1, row 0)"},
    world.newTileMap, world, {tile = 16, rows = {"#/"}})
  t.equal(world:getBodyCount(), 0, "nothing made")
  local map = world:newTileMap({tile = 16, rows = {"#."}})
  t.raises({"TileMap:setTile", "the classic model has sharp boxes only"}, map.setTile, map, 1, 0, "/")
  t.equal(map:tileOf(1, 0), ".", "left as it was")
end)

test("a one-way map takes no ramp tiles", function()
  local world = jostle.newWorld()
  t.raises({"World:newTileMap",
    "rows[1][2]: a one-way map has boxes only: no ramps (a ramp blocks from every side) (tile column 1, row 0)"},
    world.newTileMap, world, {tile = 16, rows = {"#/"}, oneWay = {0, -1}})
  t.equal(world:getBodyCount(), 0, "nothing made")
  local map = world:newTileMap({tile = 16, rows = {"#."}, oneWay = {0, -1}})
  t.raises({"TileMap:setTile", "a one-way map has boxes only"}, map.setTile, map, 1, 0, "/")
  t.equal(map:tileOf(1, 0), ".", "left as it was")
end)

test("fixed step arguments", function()
  t.raises({"jostle.newFixedStep", "dt: must be a number of seconds from 1e-6 to 3600"},
    jostle.newFixedStep, 0)
  t.raises({"jostle.newFixedStep", "dt: expected a number, got string"}, jostle.newFixedStep, "1/60")
  t.raises({"jostle.newFixedStep", "maxStepsPerFrame: must be from 1 to 100000"},
    jostle.newFixedStep, 1 / 60, 0)
  local clock = jostle.newFixedStep()
  t.raises({"FixedStep:advance", "frameSeconds: must be >= 0"}, clock.advance, clock, -1)
  t.raises({"FixedStep:advance", "frameSeconds: must be a finite number"}, clock.advance, clock, 0 / 0)
  t.raises({"FixedStep:update", "world: expected a World, got number"}, clock.update, clock, 1, 1)
  t.raises({"FixedStep:getAlpha", "expected a FixedStep as self"}, clock.getAlpha)
end)

-- The message of the error that fn(...) raises, without a caller's position in front.
local function messageOf(fn, ...)
  local ok, message = pcall(fn, ...)
  t.equal(ok, false, "the call is refused")
  return (tostring(message):gsub("^[^:]*:%d+: ", ""))
end

test("one rule, in Lua's words: did you mean, {0, 0}, rows counted from 1", function()
  local world, _, box = newWorld()
  -- An unknown field near a known one names it (src/suggest.hpp); one far from all does not.
  t.equal(messageOf(world.newBody, world, {hw = 1, hh = 1, snapdown = 4}),
    'World:newBody: unknown field "snapdown" (did you mean "snapDown"?)', "snapdown")
  t.equal(messageOf(world.newBody, world, {hw = 1, hh = 1, foo = 4}),
    'World:newBody: unknown field "foo"', "foo")
  t.equal(messageOf(jostle.newWorld, {gravty = {0, 800}}),
    'jostle.newWorld: unknown field "gravty" (did you mean "gravity"?)', "gravty")
  t.equal(messageOf(jostle.newWorld, {physical = {Slop = 0.1}}),
    'jostle.newWorld: physical: unknown field "Slop" (did you mean "slop"?)', "Slop")
  t.equal(messageOf(world.newTileMap, world, {tiles = 16, rows = {"#"}}),
    'World:newTileMap: unknown field "tiles" (did you mean "tile"?)', "tiles")
  t.equal(messageOf(world.rayCast, world, 0, 0, 1, 1, {maks = 1}),
    'World:rayCast: filter: unknown field "maks" (did you mean "mask"?)', "maks")
  -- Vectors as Lua writes them: {0, -1}.
  local oneWayRule = "must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}"
  t.equal(messageOf(world.newBody, world, {hw = 1, hh = 1, oneWay = {1, 1}}),
    "World:newBody: oneWay: " .. oneWayRule, "newBody's oneWay")
  t.equal(messageOf(box.setOneWay, box, 1, 1), "Body:setOneWay: normal " .. oneWayRule, "setOneWay")
  t.equal(messageOf(world.newTileMap, world, {tile = 16, rows = {"#"}, oneWay = {0, 2}}),
    "World:newTileMap: oneWay: " .. oneWayRule, "newTileMap's oneWay")
  -- Rows counted as Lua counts: rows[1] is the first; a tile's coordinates from 0.
  t.equal(messageOf(world.newTileMap, world, {tile = 16, rows = {"#..#", "###"}}),
    "World:newTileMap: rows[2]: has 3 columns, rows[1] has 4", "a ragged map")
  t.equal(messageOf(world.newTileMap, world, {tile = 16, rows = {"", ""}}),
    "World:newTileMap: rows[1]: must have at least one column", "an empty row")
  t.equal(messageOf(world.newTileMap, world, {tile = 16, rows = {"##", "#{"}}),
    "World:newTileMap: rows[2][2]: expected '#', '.' or a ramp, got '{' (tile column 1, row 1)",
    "a character that is no tile's")
  -- A definition's field as newBody takes it.
  t.equal(messageOf(box.setWalkSpeed, box, 50),
    "Body:setWalkSpeed: the body is not a character (a dynamic body with character = true)",
    "walking a crate")
  t.equal(world:getBodyCount(), 2, "nothing refused was made")
end)

test("error messages carry the caller's position", function()
  local world = jostle.newWorld()
  local ok, message = pcall(function() world:step(0) end)
  t.equal(ok, false, "raised")
  t.truthy(message:find("test_errors.lua:%d+: World:step: dt: must be > 0"), "position in " .. message)
end)

return t.run(tests)
