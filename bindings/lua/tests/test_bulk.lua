-- Reading a whole world at once: world:getPositions, getVelocities and getHalfExtents into a flat array,
-- the FFI buffers of LuaJIT (getPositionsBuffer, getVelocitiesBuffer), and the fixed
-- step's interpolated positions (clock:getDrawPosition, getDrawPositions).
local jostle = require("jostle")
local t = require("helper")

local dt = 1 / 60

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A floor, a pile of boxes thrown every which way, a kinematic lift and a sensor.
local function busyWorld()
  local world = jostle.newWorld({gravity = {0, 800}})
  world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
  for i = 1, 30 do
    world:newBody({x = -300 + 20 * i, y = 200 - 13 * (i % 7), hw = 4 + i % 5, hh = 3 + i % 4,
      vx = 37 * (i % 9) - 140, vy = -11 * (i % 6)})
  end
  world:newBody({type = "kinematic", x = 0, y = 100, hw = 40, hh = 6, vx = 25, vy = -10})
  world:newBody({type = "static", x = 100, y = 250, hw = 10, hh = 10, sensor = true})
  t.steps(world, 20)
  return world
end

test("getPositions, getVelocities, getHalfExtents: {x1, y1, ...} in the order of getBodies, as each body's getter reads", function()
  local world = busyWorld()
  local positions = world:getPositions()
  local velocities = world:getVelocities()
  local halves = world:getHalfExtents()
  local bodies = world:getBodies()
  t.equal(#positions, 2 * #bodies, "two numbers a body")
  t.equal(#halves, 2 * #bodies, "two numbers a body")
  t.equal(#velocities, 2 * #bodies, "two numbers a body")
  for i, body in ipairs(bodies) do
    local x, y = body:getPosition()
    t.equal(positions[2 * i - 1], x, "x of body " .. i)
    t.equal(positions[2 * i], y, "y of body " .. i)
    local vx, vy = body:getVelocity()
    t.equal(velocities[2 * i - 1], vx, "vx of body " .. i)
    t.equal(velocities[2 * i], vy, "vy of body " .. i)
    local hw, hh = body:getHalfExtents()
    t.equal(halves[2 * i - 1], hw, "hw of body " .. i)
    t.equal(halves[2 * i], hh, "hh of body " .. i)
  end
  t.truthy(world:getHalfExtents(positions) == positions, "getHalfExtents(t) fills t too")
  t.raises({"World:getHalfExtents", "t: expected a table, got number"}, world.getHalfExtents,
    world, 1)
end)

test("getPositions(t) fills t and returns it; a shorter read clears the rest", function()
  local world = busyWorld()
  local into = {name = "kept"}
  t.truthy(world:getPositions(into) == into, "the same table back")
  local count = world:getBodyCount()
  t.equal(#into, 2 * count, "filled")
  t.equal(into.name, "kept", "other keys are left alone")
  -- Fewer bodies: the entries beyond them go, so #t stays two a body.
  local bodies = world:getBodies()
  for i = 1, 10 do bodies[i]:destroy() end
  world:getPositions(into)
  t.equal(#into, 2 * (count - 10), "shorter")
  t.equal(into[2 * (count - 10) + 1], nil, "nothing beyond")
  local first = world:getBodies()[1]
  t.equal(into[1], (first:getPosition()), "the first body now")
  t.truthy(world:getVelocities(into) == into, "getVelocities(t) too")
  t.equal(into[1], (first:getVelocity()), "velocities now")
  -- An empty world: an empty array.
  local empty = jostle.newWorld()
  t.equal(#empty:getPositions(), 0, "empty")
  t.equal(#empty:getPositions(into), 0, "empty, into t")
  t.raises({"World:getPositions", "t: expected a table, got number"}, world.getPositions, world, 1)
  t.raises({"World:getVelocities", "t: expected a table, got string"}, world.getVelocities, world,
    "t")
end)

if jit then
  test("LuaJIT: the FFI buffers hold what getPosition and getVelocity read", function()
    local ffi = require("ffi")
    local world = busyWorld()
    local pointer, count = world:getPositionsBuffer()
    t.equal(type(pointer), "userdata", "a light userdata")
    t.equal(count, world:getBodyCount(), "the body count")
    local p = ffi.cast("float*", pointer)
    local vpointer, vcount = world:getVelocitiesBuffer()
    local v = ffi.cast("float*", vpointer)
    t.equal(vcount, count, "as many velocities")
    for i, body in ipairs(world:getBodies()) do
      local x, y = body:getPosition()
      t.equal(p[2 * (i - 1)], x, "x of body " .. i)
      t.equal(p[2 * (i - 1) + 1], y, "y of body " .. i)
      local vx, vy = body:getVelocity()
      t.equal(v[2 * (i - 1)], vx, "vx of body " .. i)
      t.equal(v[2 * (i - 1) + 1], vy, "vy of body " .. i)
    end
    -- A snapshot: a step does not change it; the next call reads the world again.
    local before, vx0 = p[1], v[0]
    world:step(dt)
    t.equal(p[1], before, "unchanged by a step")
    p = ffi.cast("float*", (world:getPositionsBuffer()))
    t.equal(p[1], select(2, world:getBodies()[1]:getPosition()), "read again")
    -- The velocities' buffer is its own: reading positions left it alone.
    t.equal(v[0], vx0, "velocities kept")
    local _, none = jostle.newWorld():getPositionsBuffer()
    t.equal(none, 0, "an empty world: 0 bodies")
  end)
else
  test("Lua 5.4: no FFI, so no buffers", function()
    local world = jostle.newWorld()
    t.equal(world.getPositionsBuffer, nil, "getPositionsBuffer is LuaJIT's")
    t.equal(world.getVelocitiesBuffer, nil, "getVelocitiesBuffer is LuaJIT's")
  end)
end

test("clock:getDrawPosition: between the last two steps, by alpha", function()
  -- Steps of 0.25 s; a box moving at 4 units/s covers 1 a step, so its positions after
  -- each step are whole numbers and what lies between them is alpha (fixed_step.hpp's test).
  local world = jostle.newWorld()
  local box = world:newBody({x = 0, y = 0, hw = 1, hh = 1, vx = 4})
  local clock = jostle.newFixedStep(0.25)
  t.equal(clock:getDrawPosition(world, box), 0, "nothing stepped yet")
  t.equal(clock:update(world, 0.375), 1, "1.5 steps: at 1, alpha 0.5")
  t.near(clock:getDrawPosition(world, box), 0.5, 1e-6, "half way from 0 to 1")
  t.equal(clock:update(world, 0.5), 2, "2 steps: at 3, alpha 0.5")
  t.near(clock:getDrawPosition(world, box), 2.5, 1e-6, "half way from 2 to 3")
  t.equal(clock:update(world, 0.125), 1, "0.125 + 0.125: at 4, alpha 0")
  t.near(clock:getDrawPosition(world, box), 3, 1e-6, "at 3")
  t.equal(clock:update(world, 0.125), 0, "no step: alpha 0.5")
  local x, y = clock:getDrawPosition(world, box)
  t.near(x, 3.5, 1e-6, "x")
  t.equal(y, 0, "y")
  -- A body made since the last step is drawn where it is.
  local late = world:newBody({x = 7, y = 0, hw = 1, hh = 1, vx = 4})
  t.equal(clock:getDrawPosition(world, late), 7, "a new body")
  -- All at once, in the order of getBodies.
  local all = clock:getDrawPositions(world)
  t.equal(#all, 4, "two bodies")
  t.near(all[1], 3.5, 1e-6, "the box")
  t.equal(all[3], 7, "the late one")
  local into = {1, 2, 3, 4, 5, 6}
  t.truthy(clock:getDrawPositions(world, into) == into, "into t")
  t.equal(#into, 4, "its tail cleared")
  -- A slot reused by another body is not mistaken for the old one.
  box:destroy()
  local reused = world:newBody({x = -5, y = 0, hw = 1, hh = 1})
  t.equal(clock:getDrawPosition(world, reused), -5, "the new body in the old slot")
  t.raises({"FixedStep:getDrawPosition", "body: the body was destroyed"}, clock.getDrawPosition,
    clock, world, box)
  local elsewhere = jostle.newWorld()
  t.raises({"FixedStep:getDrawPosition", "body: the body belongs to another world"},
    clock.getDrawPosition, clock, elsewhere, reused)
  t.raises({"FixedStep:getDrawPositions", "expected a World"}, clock.getDrawPositions, clock, box)
end)

test("clock:rememberPositions: interpolating a world stepped by hand", function()
  local world = jostle.newWorld()
  local box = world:newBody({x = 0, y = 0, hw = 1, hh = 1, vx = 4})
  local clock = jostle.newFixedStep(0.25)
  local steps = clock:advance(0.625) -- 2.5 steps: 2 now, alpha 0.5
  t.equal(steps, 2, "steps")
  for i = 1, steps do
    if i == steps then clock:rememberPositions(world) end
    world:step(clock:getDt())
  end
  t.near(clock:getDrawPosition(world, box), 1.5, 1e-6, "half way from 1 to 2")
  t.raises({"FixedStep:rememberPositions", "expected a World"}, clock.rememberPositions, clock)
end)

return t.run(tests)
