-- world:move, bump.lua's world:move: the cases of tests/test_move.cpp (bump.lua's spec
-- suite in jostle's terms), its filter function and the collisions it returns, and errors
-- raised in the filter.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A box given as bump.lua gives it: top-left corner (x, y), width and height.
local function rect(x, y, w, h, kind)
  return {type = kind or "static", x = x + w / 2, y = y + h / 2, hw = w / 2, hh = h / 2}
end

-- A world without gravity and the item moved: (0, 0, 1, 1), a kinematic body at rest.
local function newWorld()
  local world = jostle.newWorld()
  return world, world:newBody(rect(0, 0, 1, 1, "kinematic"))
end

local function always(response)
  return function() return response end
end

test("in an empty world the body goes all the way, and is put there", function()
  local world, item = newWorld()
  local x, y, cols, len = world:move(item, 1, 1)
  t.equal(x, 1.5, "x")
  t.equal(y, 1.5, "y")
  t.equal(#cols, 0, "no collisions")
  t.equal(len, 0, "len")
  local px, py = item:getPosition()
  t.equal(px, 1.5, "the body's x")
  t.equal(py, 1.5, "the body's y")
end)

test("touch: stops where the bodies meet; a collision as bump.lua names its fields", function()
  local world, item = newWorld()
  local b = world:newBody(rect(0, 2, 1, 1))
  world:newBody(rect(0, 3, 1, 1))
  local x, y, cols, len = world:move(item, 0, 5, always("touch"))
  -- Its bottom (1) reaches b's top (2) after 1 of 5.
  t.equal(x, 0.5, "x")
  t.equal(y, 1.5, "y")
  t.equal(len, 1, "len")
  local col = cols[1]
  t.truthy(col.item == item, "item: the body moved")
  t.truthy(col.other == b, "other")
  t.equal(col.type, "touch", "type")
  t.equal(col.normal.x, 0, "normal.x")
  t.equal(col.normal.y, -1, "normal.y")
  t.equal(col.touch.x, 0.5, "touch.x: the centre, not bump's top-left corner")
  t.equal(col.touch.y, 1.5, "touch.y")
  t.near(col.ti, 0.2, 1e-6, "ti: a fifth of the move")
  t.equal(col.otherRect.x, 0, "otherRect.x: the other's left")
  t.equal(col.otherRect.y, 2, "otherRect.y: its top")
  t.equal(col.otherRect.w, 1, "otherRect.w")
  t.equal(col.otherRect.h, 1, "otherRect.h")
  t.equal(select(2, item:getPosition()), 1.5, "the body is where the move ended")
end)

test("cross: goes through and reports each in turn", function()
  local world, item = newWorld()
  local b = world:newBody(rect(0, 2, 1, 1))
  local c = world:newBody(rect(0, 3, 1, 1))
  local x, y, cols, len = world:move(item, 0, 5, always("cross"))
  t.equal(x, 0.5, "x")
  t.equal(y, 5.5, "y: all the way")
  t.equal(len, 2, "len")
  t.truthy(cols[1].other == b, "b first")
  t.near(cols[1].ti, 0.2, 1e-6, "b's ti")
  t.truthy(cols[2].other == c, "then c")
  t.near(cols[2].ti, 0.4, 1e-6, "c's ti")
  t.equal(cols[2].touch.y, 2.5, "c's touch")
  t.equal(cols[2].type, "cross", "type")
end)

test("slide: stops along the normal and goes on along the face", function()
  -- b (0, 2, 1, 2) below the item, c (2, 1, 1, 1). Moving by (5, 5), it meets c's left
  -- face after 1 of 5 at (1.5, 1.5), then slides down the rest, to (1.5, 5.5), passing
  -- b's corner exactly. The default response: no filter.
  local world, item = newWorld()
  world:newBody(rect(0, 2, 1, 2))
  local c = world:newBody(rect(2, 1, 1, 1))
  local x, y, cols, len = world:move(item, 5, 5)
  t.equal(x, 1.5, "x")
  t.equal(y, 5.5, "y")
  t.equal(len, 1, "len")
  t.truthy(cols[1].other == c, "c")
  t.equal(cols[1].type, "slide", "type")
  t.equal(cols[1].normal.x, -1, "normal.x")
  t.equal(cols[1].touch.x, 1.5, "touch.x")
  t.equal(cols[1].touch.y, 1.5, "touch.y")
  t.near(cols[1].ti, 0.2, 1e-6, "ti")
end)

test("bounce: the rest of the move turns back", function()
  -- Down 5 onto b's top after 1: the 4 left go back up, from 1.5 to -2.5.
  local world, item = newWorld()
  world:newBody(rect(0, 2, 1, 2))
  local x, y, cols = world:move(item, 0, 5, always("bounce"))
  t.equal(x, 0.5, "x")
  t.equal(y, -2.5, "y")
  t.equal(cols[1].type, "bounce", "type")
  t.equal(cols[1].touch.y, 1.5, "touch.y")
end)

test("a floor and a wall met together are both reported, in creation order", function()
  local world = newWorld()
  local big = world:newBody(rect(0, 0, 10, 10, "kinematic"))
  local floor = world:newBody(rect(-20, 20, 100, 10))
  local wall = world:newBody(rect(20, -40, 10, 60))
  local x, y, cols, len = world:move(big, 20, 20)
  t.equal(x, 15, "x")
  t.equal(y, 15, "y")
  t.equal(len, 2, "len")
  t.truthy(cols[1].other == floor, "the floor first")
  t.truthy(cols[2].other == wall, "then the wall")
  t.near(cols[1].ti, 0.5, 1e-6, "half way")
end)

test("nothing is tunnelled through, and seams do not snag", function()
  local world, item = newWorld()
  world:newBody(rect(50, -5, 1, 10))
  t.equal(world:move(item, 100, 0), 49.5, "stopped by the thin wall")
  -- Pressed into a column of 10 x 10 boxes while falling past three seams.
  local player = world:newBody(rect(-10, -30, 10, 10, "kinematic"))
  local first = world:newBody(rect(0, -20, 10, 10))
  world:newBody(rect(0, -10, 10, 10))
  world:newBody(rect(0, 0, 10, 10))
  local x, y, cols, len = world:move(player, 2, 35)
  t.equal(x, -5, "x: against the column")
  t.equal(y, 10, "y: all the way down")
  t.equal(len, 1, "one collision")
  t.truthy(cols[1].other == first, "the first box only")
end)

test("a body starting inside another is free to leave", function()
  local world = newWorld()
  local inside = world:newBody(rect(3, 3, 2, 2, "kinematic"))
  world:newBody(rect(0, 0, 8, 8))
  local x, y, _, len = world:move(inside, 0, 17)
  t.equal(x, 4, "x")
  t.equal(y, 21, "y")
  t.equal(len, 0, "no collision")
end)

test("the filter is asked once a body, with the other body; nil and false ignore", function()
  local world, item = newWorld()
  local ghost = world:newBody(rect(3, 0, 1, 1))
  local mist = world:newBody(rect(5, 0, 0.5, 1))
  local wall = world:newBody(rect(7, 0, 1, 1))
  local asked = {}
  local x, _, cols, len = world:move(item, 10, 0, function(other)
    asked[other] = (asked[other] or 0) + 1
    if other == ghost then return nil end
    if other == mist then return false end
    return "slide"
  end)
  t.equal(x, 6.5, "through the ghost and the mist, stopped by the wall")
  t.equal(len, 1, "only the wall reported")
  t.truthy(cols[1].other == wall, "the wall")
  for body, times in pairs(asked) do
    t.equal(times, 1, "asked about " .. tostring(body))
  end
  t.truthy(asked[ghost] and asked[wall], "asked about those in the way")
  t.equal(asked[item], nil, "never about the body moved")
end)

test("without a filter: sensors are crossed, and the body's mask leaves others out", function()
  local world, item = newWorld()
  local coin = world:newBody({type = "static", x = 3.5, y = 0.5, hw = 0.5, hh = 0.5,
    sensor = true})
  world:newBody({type = "static", x = 6.5, y = 0.5, hw = 0.5, hh = 0.5, category = 4})
  item:setMask(0xFFFFFFFF - 4)
  local x, _, cols, len = world:move(item, 10, 0)
  t.equal(x, 10.5, "all the way")
  t.equal(len, 1, "one collision")
  t.truthy(cols[1].other == coin, "the coin")
  t.equal(cols[1].type, "cross", "crossed")
end)

test("a one-way platform stops the body only from its blocking side", function()
  local world, item = newWorld()
  world:newBody({type = "static", x = 0.5, y = -5, hw = 5, hh = 0.5, oneWay = {0, -1}})
  t.equal(select(2, world:move(item, 0, -10)), -9.5, "up through it")
  local _, y, _, len = world:move(item, 0, 10)
  t.equal(y, -6, "down onto it")
  t.equal(len, 1, "one collision")
end)

test("a dynamic character body can be moved too; its velocity is left alone", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  world:newBody(rect(-100, 0, 200, 10))
  local hero = world:newBody({x = 0, y = -20, hw = 6, hh = 8, vx = 5, character = true})
  local _, y = world:move(hero, 0, 100)
  t.equal(y, -8, "on the floor")
  t.equal(hero:getVelocity(), 5, "vx kept")
end)

-- --- Errors ---------------------------------------------------------------------------------

test("an error raised in the filter comes out of move as it was; nothing moved", function()
  local world, item = newWorld()
  world:newBody(rect(3, 0, 1, 1))
  local message = t.raises({"test_move.lua:", "filter failed"}, world.move, world, item, 10, 0,
    function() error("filter failed") end)
  t.truthy(message:find("test_move.lua:%d+: filter failed"), "keeps its position: " .. message)
  local value = {reason = "a table"}
  local ok, got = pcall(world.move, world, item, 10, 0, function() error(value) end)
  t.equal(ok, false, "raised")
  t.truthy(got == value, "the same table")
  t.equal(item:getPosition(), 0.5, "the body did not move")
  -- The world goes on: a move, a step.
  t.equal(world:move(item, 10, 0), 2.5, "moves again, stopped by the box")
  world:step(1 / 60)
end)

test("a filter returning something else is an error naming what it returned", function()
  local world, item = newWorld()
  world:newBody(rect(3, 0, 1, 1))
  t.raises({"World:move", 'filter returned "slid"', '"slide", "touch", "cross", "bounce"',
    "nil or false"}, world.move, world, item, 10, 0, always("slid"))
  t.raises({"World:move", "filter returned true"}, world.move, world, item, 10, 0, always(true))
  t.raises({"World:move", "filter returned table"}, world.move, world, item, 10, 0, always({}))
  t.equal(item:getPosition(), 0.5, "the body did not move")
end)

test("the filter may read the world but not change it", function()
  local world, item = newWorld()
  local box = world:newBody(rect(3, 0, 1, 1))
  local map
  local changes = {
    {"Body:setPosition", function(other) other:setPosition(100, 100) end},
    {"Body:destroy", function(other) other:destroy() end},
    {"Body:applyImpulse", function(other) other:applyImpulse(1, 0) end},
    {"World:newBody", function() world:newBody(rect(50, 50, 1, 1)) end},
    {"World:step", function() world:step(1 / 60) end},
    {"World:move", function() world:move(item, 1, 0) end},
    {"World:setGravity", function() world:setGravity(0, 1) end},
    {"World:destroy", function() world:destroy() end},
    {"World:newTileMap", function() world:newTileMap({tile = 1, rows = {"#"}}) end},
    {"TileMap:setTile", function() map:setTile(0, 0, false) end},
  }
  map = world:newTileMap({x = 100, y = 100, tile = 1, rows = {"#"}})
  for _, case in ipairs(changes) do
    t.raises({case[1], "called from World:move's filter"}, world.move, world, item, 10, 0,
      function(other) case[2](other) end)
  end
  -- Reading is fine: positions, queries, user data.
  local seen
  world:move(item, 10, 0, function(other)
    seen = {other:getPosition(), #world:queryPoint(3.5, 0.5)}
    other:setUserData("seen")
    return "slide"
  end)
  t.equal(seen[1], 3.5, "read the other's position")
  t.equal(seen[2], 1, "queried the world")
  t.equal(box:getUserData(), "seen", "user data is the game's, not the world's")
  t.equal(world:getBodyCount(), 3, "nothing was added or removed")
end)

test("move's arguments", function()
  local world, item = newWorld()
  local other = jostle.newWorld():newBody({x = 0, y = 0, hw = 1, hh = 1})
  t.raises({"World:move", "body: expected a Body, got number"}, world.move, world, 1, 2, 3)
  t.raises({"World:move", "body: the body belongs to another world"}, world.move, world, other,
    1, 0)
  t.raises({"World:move", "dy: expected a number, got no value"}, world.move, world, item, 1)
  t.raises({"World:move", "dx: must be a finite number"}, world.move, world, item, 0 / 0, 0)
  t.raises({"World:move", "filter: expected a function or nil, got table"}, world.move, world,
    item, 1, 0, {})
  t.raises({"World:move", "magnitude <= 1e9"}, world.move, world, item, 2e9, 0)
end)

return t.run(tests)
