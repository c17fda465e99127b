-- Debug drawing: world:debugDraw(draw [, options]) calls the table's functions with what
-- the engine sees, in world units and colours as 0xRRGGBBAA; jostle.rgba splits a colour.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A recorder: every call, with its arguments.
local function recorder(only)
  local calls = {}
  local draw = {}
  for _, name in ipairs(only or {"line", "box", "roundedBox", "triangle", "point"}) do
    draw[name] = function(...) calls[#calls + 1] = {name, ...} end
  end
  return draw, calls
end

local function calls_of(calls, name)
  local found = {}
  for _, call in ipairs(calls) do
    if call[1] == name then found[#found + 1] = call end
  end
  return found
end

local function level()
  local world = jostle.newWorld({gravity = {0, 10}, sleeping = false})
  world:newBody({type = "static", x = 0, y = 1, hw = 10, hh = 1})
  world:newBody({x = 0, y = -0.5, hw = 0.5, hh = 0.5, radius = 0.5})
  world:newBody({type = "static", x = 10, y = 20, hw = 2, hh = 1, slope = {1, -1}})
  t.steps(world, 60, 1 / 60)
  return world
end

test("each shape is one call, in world units, with its colours", function()
  local world = level()
  local draw, calls = recorder()
  world:debugDraw(draw)
  t.equal(#calls, 3, "three bodies, three calls")
  local floor = calls_of(calls, "box")[1]
  t.equal(floor[2], 0, "x") t.equal(floor[3], 1, "y")
  t.equal(floor[4], 10, "hw") t.equal(floor[5], 1, "hh")
  -- Static grey 150 150 150, opaque; its outline 60 % of that, 90.
  t.equal(floor[6], 0x969696FF, "the floor's fill")
  t.equal(floor[7], 0x5A5A5AFF, "the floor's outline")
  local ball = calls_of(calls, "roundedBox")[1]
  t.equal(ball[6], 0.5, "the ball's radius")
  -- The ramp's slope names the corner (+x, -y): its face runs from (+x, +y) to (-x, -y),
  -- its right angle at (-x, +y).
  local ramp = calls_of(calls, "triangle")[1]
  t.equal(ramp[2], 12, "x1") t.equal(ramp[3], 21, "y1")
  t.equal(ramp[4], 8, "x2") t.equal(ramp[5], 19, "y2")
  t.equal(ramp[6], 8, "x3") t.equal(ramp[7], 21, "y3")
end)

test("contacts are a point and a normal into the body pushed", function()
  local world = level()
  local draw, calls = recorder()
  world:debugDraw(draw, {shapes = false, contacts = true, markLength = 0.25})
  local points, lines = calls_of(calls, "point"), calls_of(calls, "line")
  t.equal(#points, 1, "one touching pair")
  t.near(points[1][3], 0, 1e-2, "on the floor's top, y = 0")
  t.equal(#lines, 1, "and its normal")
  t.near(lines[1][5] - lines[1][3], -0.25, 1e-6, "up into the ball, markLength long")
  t.equal(lines[1][6], 0xFAFA78FF, "in the contact colour")
end)

test("a renderer of lines alone gets every shape in lines", function()
  local world = level()
  local draw, calls = recorder({"line"})
  world:debugDraw(draw)
  -- The box's 4 sides, the ramp's 3, the ball's ring of 4 arcs of 6 lines each.
  t.equal(#calls, 4 + 3 + 4 * 6, "every shape in lines")
end)

test("options and the palette are read by name", function()
  local world = level()
  local draw, calls = recorder()
  world:debugDraw(draw, {viewMin = {-1, -1}, viewMax = {1, 1},
                         palette = {staticBody = 0x102030FF, outlinePercent = 50}})
  t.equal(#calls, 2, "the ramp is out of view")
  t.equal(calls[1][6], 0x102030FF, "the floor in its new colour")
  t.equal(calls[1][7], 0x081018FF, "outlined at half of it")
end)

test("jostle.rgba gives a colour's parts from 0 to 1", function()
  local draw, calls = recorder()
  level():debugDraw(draw)
  t.equal(string.format("%08x", calls[1][6]), "969696ff", "colours are whole numbers")
  local r, g, b, a = jostle.rgba(0xFF8000FF)
  t.equal(r, 1, "red") t.near(g, 128 / 255, 1e-9, "green") t.equal(b, 0, "blue") t.equal(a, 1, "alpha")
  t.raises({"jostle.rgba", "0xFFFFFFFF"}, jostle.rgba, -1)
end)

test("bad arguments and a function's own error", function()
  local world = level()
  t.raises({"World:debugDraw", "draw: expected a table"}, world.debugDraw, world, nil)
  t.raises({"World:debugDraw", "draw.line: expected a function"}, world.debugDraw, world, {})
  t.raises({"World:debugDraw", "draw.box: expected a function or nil"}, world.debugDraw, world,
    {line = function() end, box = 3})
  t.raises({"World:debugDraw", "options.markLength"}, world.debugDraw, world,
    {line = function() end}, {markLength = -1})
  t.raises({"World:debugDraw", "unknown field \"grd\"", "grid"}, world.debugDraw, world,
    {line = function() end}, {grd = true})
  t.raises({"World:debugDraw", "options.palette.sleepingPercent must be in [0, 100]"},
    world.debugDraw, world, {line = function() end}, {palette = {sleepingPercent = 200}})
  t.raises({"World:debugDraw", "called from a function of world:debugDraw"}, world.debugDraw,
    world, {line = function() world:debugDraw({line = function() end}) end})
  t.raises({"World:destroy", "called from a function of world:debugDraw"}, world.debugDraw,
    world, {line = function() world:destroy() end})
  t.truthy(not world:isDestroyed(), "the world is still there")
  -- Changing the world from a function is allowed: it runs once the walk is done.
  world:debugDraw({line = function() end, box = function() world:setGravity(0, 20) end})
  t.equal(select(2, world:getGravity()), 20, "the world changed from a function")
  local seen = 0
  t.raises({"from the renderer"}, world.debugDraw, world,
    {line = function() end, box = function() seen = seen + 1; error("from the renderer") end})
  t.equal(seen, 1, "no call after the first error")
end)

return t.run(tests)
