-- Queries, with results derived by hand from the boxes' edges.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A floor with its top at y = 290 and a crate resting on it; no gravity, so nothing moves.
local function scene()
  local world = jostle.newWorld()
  local floor = world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
  local crate = world:newBody({x = 100, y = 280, hw = 10, hh = 10, category = 2})
  return world, floor, crate
end

test("queryPoint: the bodies whose box holds the point, edges included", function()
  local world, floor, crate = scene()
  local found = world:queryPoint(100, 285)
  t.equal(#found, 1, "inside the crate")
  t.truthy(found[1] == crate, "the crate")
  -- y = 290 is the crate's bottom edge and the floor's top edge: both.
  found = world:queryPoint(100, 290)
  t.equal(#found, 2, "on the seam")
  t.truthy(found[1] == floor and found[2] == crate, "in creation order")
  t.equal(#world:queryPoint(0, 0), 0, "empty space")
end)

test("queryBox and queryRect: sharing area counts, touching does not", function()
  local world, floor, crate = scene()
  -- A box whose bottom edge is the floor's top: touches, does not overlap.
  local found = world:queryBox(-200, 280, 10, 10)
  t.equal(#found, 0, "a box resting on the floor overlaps nothing")
  found = world:queryBox(100, 285, 1, 1)
  t.truthy(#found == 1 and found[1] == crate, "inside the crate")
  found = world:queryRect(95, 285, 105, 295)
  t.truthy(#found == 2 and found[1] == floor and found[2] == crate, "across both")
end)

test("filters: mask, category, ignore, sensors", function()
  local world, floor, crate = scene()
  local zone = world:newBody({type = "static", x = 100, y = 280, hw = 50, hh = 50, sensor = true})
  local found = world:queryPoint(100, 290)
  t.equal(#found, 2, "sensors are left out by default")
  found = world:queryPoint(100, 290, {includeSensors = true})
  t.truthy(#found == 3 and found[3] == zone, "sensors when asked")
  found = world:queryPoint(100, 290, {mask = 2})
  t.truthy(#found == 1 and found[1] == crate, "mask 2: the crate's category only")
  found = world:queryPoint(100, 290, {ignore = crate})
  t.truthy(#found == 1 and found[1] == floor, "ignore the crate")
  crate:setMask(1) -- the crate collides with category 1 only
  found = world:queryPoint(100, 290, {category = 4})
  t.truthy(#found == 1 and found[1] == floor, "a query of category 4 passes the crate")
end)

test("rayCast: the hit point, normal and fraction by hand", function()
  local world, floor, crate = scene()
  -- Straight down at x = -50: meets the floor's top, y = 290, at 290 / 400 of the way.
  local body, x, y, nx, ny, fraction = world:rayCast(-50, 0, -50, 400)
  t.truthy(body == floor, "the floor")
  t.equal(x, -50, "x")
  t.equal(y, 290, "y")
  t.equal(nx, 0, "nx")
  t.equal(ny, -1, "ny: the floor's top faces up")
  t.near(fraction, 290 / 400, 1e-6, "fraction")
  -- From the left along y = 280: meets the crate's left face, x = 90.
  body, x, y, nx, ny, fraction = world:rayCast(0, 280, 200, 280)
  t.truthy(body == crate, "the crate")
  t.equal(x, 90, "x at the crate's left face")
  t.equal(y, 280, "y")
  t.equal(nx, -1, "nx")
  t.equal(ny, 0, "ny")
  t.near(fraction, 90 / 200, 1e-6, "fraction")
  t.equal(world:rayCast(0, 0, 0, 100), nil, "a miss is nil")
end)

test("rayCastAll: every body, nearest first", function()
  local world, floor, crate = scene()
  -- Down through the crate (top at 270) and into the floor (top at 290).
  local hits = world:rayCastAll(100, 0, 100, 400)
  t.equal(#hits, 2, "two hits")
  t.truthy(hits[1].body == crate and hits[2].body == floor, "crate, then floor")
  t.equal(hits[1].y, 270, "the crate's top")
  t.equal(hits[2].y, 290, "the floor's top")
  t.near(hits[1].fraction, 270 / 400, 1e-6, "fraction 1")
  t.equal(hits[1].ny, -1, "ny")
  t.equal(hits[1].x, 100, "x")
  t.equal(#world:rayCastAll(0, 0, 0, 100), 0, "no hits: an empty array")
end)

test("boxCast: where a moving box stops", function()
  local world, floor = scene()
  -- A 20 x 20 box falling from y = 0 at x = -200 stops with its bottom on y = 290.
  local body, x, y, nx, ny, fraction = world:boxCast(-200, 0, 10, 10, 0, 400)
  t.truthy(body == floor, "the floor")
  t.equal(x, -200, "x")
  t.equal(y, 280, "centre stops at 290 - 10")
  t.equal(nx, 0, "nx")
  t.equal(ny, -1, "ny: from the floor towards the box")
  t.near(fraction, 280 / 400, 1e-6, "fraction")
  t.equal(world:boxCast(-200, 0, 10, 10, 0, 100), nil, "short of the floor: nil")
end)

test("moveAndSlide: a box slides along the floor and reports it", function()
  local world, floor, crate = scene()
  -- From (-200, 270) by (30, 50): down onto the floor (centre y = 280), then along it.
  local x, y, hits = world:moveAndSlide(-200, 270, 10, 10, 30, 50)
  t.near(x, -170, 1e-4, "x: the whole sideways motion")
  t.equal(y, 280, "y: stopped on the floor")
  t.equal(#hits, 1, "one hit")
  t.truthy(hits[1].body == floor, "the floor")
  t.equal(hits[1].nx, 0, "nx")
  t.equal(hits[1].ny, -1, "ny: grounded")
  -- Into the crate's left face (x = 90) from the left: stops at 90 - 10.
  x, y, hits = world:moveAndSlide(50, 280, 10, 10, 100, 0, {mask = 2})
  t.equal(x, 80, "stopped by the crate")
  t.equal(y, 280, "y unchanged")
  t.truthy(#hits == 1 and hits[1].body == crate and hits[1].nx == -1, "the crate, from the left")
  -- Nothing in the way: the whole translation, no hits.
  x, y, hits = world:moveAndSlide(0, 0, 5, 5, 10, -20)
  t.truthy(x == 10 and y == -20 and #hits == 0, "free motion")
end)

test("a character moved by hand with moveAndSlide lands and walks (bump.lua style)", function()
  local world, floor = scene()
  local player = world:newBody({type = "kinematic", x = -300, y = 200, hw = 6, hh = 12})
  local vx, vy, grounded = 120, 0, false
  local dt = 1 / 60
  for _ = 1, 120 do
    vy = vy + 900 * dt
    local px, py = player:getPosition()
    local hw, hh = player:getHalfExtents()
    local x, y, hits = world:moveAndSlide(px, py, hw, hh, vx * dt, vy * dt, {ignore = player})
    player:setPosition(x, y)
    grounded = false
    for _, hit in ipairs(hits) do
      if hit.ny < 0 then grounded = true end
      if hit.ny ~= 0 then vy = 0 end
    end
  end
  local x, y = player:getPosition()
  t.truthy(grounded, "grounded")
  t.equal(y, 290 - 12, "standing on the floor")
  t.near(x, -300 + 120 * 2, 1e-2, "walked for two seconds")
  t.truthy(floor ~= player, "distinct bodies")
end)

return t.run(tests)
