-- Rounded bodies, ramps and segments in body tables (radius, slope = {x, y}, segment):
-- given to newBody, given back by getDef, refused with the rules of checkBodyDef, and
-- refused by the classic model.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- The shape of a body as getDef gives it: radius, slope's x and y, segment.
local function shapeOf(body)
  local def = body:getDef()
  return def.radius, def.slope[1], def.slope[2], def.segment
end

local function expectShape(body, radius, sx, sy, segment, what)
  local r, x, y, s = shapeOf(body)
  t.equal(r, radius, what .. ": radius")
  t.equal(x, sx, what .. ": slope[1]")
  t.equal(y, sy, what .. ": slope[2]")
  t.equal(s, segment, what .. ": segment")
end

test("radius, slope and segment: in the definition, getDef and a copy", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local shapes = {
    {"box", {x = 0, y = 100, hw = 200, hh = 10, type = "static"}, 0, 0, 0, false},
    {"circle", {x = 0, y = 0, hw = 5, hh = 5, radius = 5}, 5, 0, 0, false},
    {"capsule", {x = 20, y = 0, hw = 3, hh = 8, radius = 3}, 3, 0, 0, false},
    {"rounded box", {x = 40, y = 0, hw = 6, hh = 4, radius = 1.5}, 1.5, 0, 0, false},
    {"ramp", {type = "static", x = -100, y = 70, hw = 40, hh = 20, slope = {-1, -1}},
      0, -1, -1, false},
    {"segment", {type = "kinematic", x = 100, y = 70, hw = 40, hh = 20, slope = {1, -1},
      segment = true}, 0, 1, -1, true},
  }
  for _, shape in ipairs(shapes) do
    local name, def, radius, sx, sy, segment = shape[1], shape[2], shape[3], shape[4], shape[5],
      shape[6]
    local body = world:newBody(def)
    expectShape(body, radius, sx, sy, segment, name)
    expectShape(world:newBody(body:getDef()), radius, sx, sy, segment, "a copy of the " .. name)
  end
  t.steps(world, 10)
  t.equal(world:getBodyCount(), 2 * #shapes, "every body made")
end)

test("the rules between the shape's fields, each named", function()
  local world = jostle.newWorld()
  local function refused(words, def)
    t.raises(words, world.newBody, world, def)
  end
  refused({"World:newBody", "radius: must be <= hw and hh"}, {hw = 5, hh = 4, radius = 4.5})
  refused({"World:newBody", "radius: must be >= 0"}, {hw = 5, hh = 5, radius = -1})
  refused({"World:newBody", "radius: expected a number, got string"},
    {hw = 5, hh = 5, radius = "round"})
  refused({"World:newBody", "slope: must be {0, 0} or each component -1 or 1"},
    {type = "static", hw = 5, hh = 5, slope = {1, 0}})
  refused({"World:newBody", "slope"}, {type = "static", hw = 5, hh = 5, slope = {1}})
  refused({"World:newBody", "slope"}, {type = "static", hw = 5, hh = 5, slope = "up"})
  refused({"World:newBody", "slope: a ramp or segment must be static or kinematic"},
    {hw = 5, hh = 5, slope = {-1, -1}})
  refused({"World:newBody", "radius: must be 0 for a ramp or segment"},
    {type = "static", hw = 5, hh = 5, slope = {-1, -1}, radius = 1})
  refused({"World:newBody", "segment: needs a slope"}, {type = "static", hw = 5, hh = 5,
    segment = true})
  refused({"World:newBody", "segment: expected true or false"},
    {type = "static", hw = 5, hh = 5, slope = {-1, -1}, segment = 1})
  refused({"World:newBody", "oneWay: must be {0, 0} for a rounded body, ramp or segment"},
    {hw = 5, hh = 5, radius = 5, oneWay = {0, -1}})
  t.equal(world:getBodyCount(), 0, "nothing made")
end)

test("a shape is fixed at creation: setters that would break it raise", function()
  local world = jostle.newWorld()
  local ball = world:newBody({hw = 5, hh = 5, radius = 5})
  local ramp = world:newBody({type = "static", x = 50, hw = 20, hh = 10, slope = {-1, -1}})
  t.raises({"Body:setType", "a ramp or segment must be static or kinematic"}, ramp.setType, ramp,
    "dynamic")
  t.equal(ramp:getType(), "static", "still static")
  t.raises({"Body:setHalfExtents", "radius"}, ball.setHalfExtents, ball, 4, 5)
  local hw, hh = ball:getHalfExtents()
  t.equal(hw + hh, 10, "still 5 x 5")
  t.raises({"Body:setOneWay", "cannot be one-way"}, ball.setOneWay, ball, 0, -1)
end)

test("the classic model has sharp boxes only", function()
  local classic = jostle.newWorld({solver = "classic"})
  t.raises({"World:newBody", "radius", "the classic model has sharp boxes only"}, classic.newBody,
    classic, {hw = 5, hh = 5, radius = 5})
  t.raises({"World:newBody", "slope", "the classic model has sharp boxes only"}, classic.newBody,
    classic, {type = "static", hw = 5, hh = 5, slope = {1, 1}})
  t.equal(classic:getBodyCount(), 0, "nothing made")

  local physical = jostle.newWorld()
  local ball = physical:newBody({hw = 5, hh = 5, radius = 5})
  t.raises({"World:setSolver", "the classic model has sharp boxes only"}, physical.setSolver,
    physical, "classic")
  t.equal(physical:getSolver(), "physical", "still physical")
  ball:destroy()
  physical:setSolver("classic")
  t.equal(physical:getSolver(), "classic", "boxes alone: classic")
end)

test("circleCast, roundedBoxCast, roundedMoveAndSlide: the cast has a curve", function()
  -- The box (0, 0) +- 1. Moving along y = -1.8 from x = -5, a box of half extent 1 meets its
  -- side at x = -2; a circle of radius 1 meets its corner (-1, -1) with its centre 1 from
  -- it: 0.8 above, so 0.6 before, at x = -1.6, normal (-0.6, -0.8), fraction 3.4 / 10.
  local world = jostle.newWorld()
  local box = world:newBody({type = "static", hw = 1, hh = 1})
  local _, x = world:boxCast(-5, -1.8, 1, 1, 10, 0)
  t.near(x, -2, 1e-5, "a box meets the side")
  local body, cx, _, nx, ny, fraction = world:circleCast(-5, -1.8, 1, 10, 0)
  t.equal(body, box, "the circle meets the box")
  t.near(cx, -1.6, 1e-3, "at its corner's curve")
  t.near(nx, -0.6, 1e-3, "normal x")
  t.near(ny, -0.8, 1e-3, "normal y")
  t.near(fraction, 0.34, 1e-4, "fraction")
  local _, rx = world:roundedBoxCast(-5, -1.8, 1, 1, 1, 10, 0)
  t.near(rx, -1.6, 1e-3, "roundedBoxCast with hw = hh = r is the circle")
  -- A capsule (1 x 3, r 1) from y = -10 moved (10, 20) onto a floor whose top is y = 0: its
  -- bottom meets it after 7 of the 20 down; the rest goes on along it, to (10, -3).
  local floorWorld = jostle.newWorld()
  floorWorld:newBody({type = "static", y = 5, hw = 50, hh = 5})
  local ex, ey, hits = floorWorld:roundedMoveAndSlide(0, -10, 1, 3, 1, 10, 20)
  t.near(ex, 10, 1e-4, "slid on to x = 10")
  t.near(ey, -3, 1e-4, "standing on the floor: y = 0 - 3")
  t.equal(#hits, 1, "one body met")
  t.raises({"World:circleCast", "r: must be > 0"}, world.circleCast, world, 0, 0, 0, 1, 0)
  t.raises({"World:roundedBoxCast", "radius"}, world.roundedBoxCast, world, 0, 0, 1, 2, 1.5, 1, 0)
end)

test("floorAngle and snapDown: in the definition, getDef, and their setters", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local hero = world:newBody({hw = 6, hh = 8, character = true, floorAngle = 45, snapDown = 4})
  local def = hero:getDef()
  t.equal(def.floorAngle, 45, "getDef().floorAngle")
  t.equal(def.snapDown, 4, "getDef().snapDown")
  hero:setFloorAngle(30)
  hero:setSnapDown(0)
  t.equal(hero:getFloorAngle(), 30, "setFloorAngle")
  t.equal(hero:getSnapDown(), 0, "setSnapDown")
  t.equal(world:newBody({hw = 1, hh = 1}):getDef().floorAngle, 60, "60 by default")
  t.raises({"Body:setFloorAngle", "[0, 90)"}, hero.setFloorAngle, hero, 90)
  t.raises({"Body:setSnapDown", ">= 0"}, hero.setSnapDown, hero, -1)
  t.raises({"World:newBody", "floorAngle"}, world.newBody, world, {hw = 1, hh = 1, floorAngle = -5})
end)

return t.run(tests)
