-- What a step reports (contacts, sensors, crushes, touching flags) and the pre-solve
-- callback, including errors raised in it.
local jostle = require("jostle")
local t = require("helper")

local g, dt = 800, 1 / 60

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A floor whose top face is at y = 0 (y grows downward), as in tests/test_events.cpp.
local function level(solver)
  local world = jostle.newWorld({gravity = {0, g}, solver = solver, sleeping = false})
  local floor = world:newBody({type = "static", x = 0, y = 50, hw = 1000, hh = 50})
  return world, floor
end

-- Steps n times, collecting the events of every step.
local function run(world, n, into)
  into = into or {begins = {}, ends = {}}
  for _ = 1, n do
    world:step(dt)
    for _, e in ipairs(world:getContactBegins()) do into.begins[#into.begins + 1] = e end
    for _, e in ipairs(world:getContactEnds()) do into.ends[#into.ends + 1] = e end
  end
  return into
end

for _, solver in ipairs({"classic", "physical"}) do
  test(solver .. ": a dropped box begins touching once, at sqrt(2 g h)", function()
    local world, floor = level(solver)
    -- Its bottom 100 above the floor.
    local box = world:newBody({x = 0, y = -105, hw = 5, hh = 5})
    local events = run(world, 120)
    t.equal(#events.begins, 1, "begin events")
    local e = events.begins[1]
    t.truthy(e.a == floor, "a is the body created first: the floor")
    t.truthy(e.b == box, "b is the box")
    t.equal(e.nx, 0, "nx")
    t.equal(e.ny, 1, "ny: from the box towards the floor")
    -- Read at the start of the step it lands in: within one step's gravity.
    t.near(e.approachSpeed, math.sqrt(2 * g * 100), g * dt + 0.5, "approach speed")
    t.equal(#events.ends, 0, "no end while it rests")
    t.truthy(box:getTouching().floor, "touching the floor")
  end)

  test(solver .. ": it ends touching when it jumps", function()
    local world, floor = level(solver)
    local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
    run(world, 30)
    box:setVelocity(0, -400)
    local events = run(world, 10)
    t.equal(#events.ends, 1, "end events")
    t.truthy(events.ends[1].a == floor and events.ends[1].b == box, "the pair")
    t.equal(events.ends[1].approachSpeed, 0, "an end's approach speed")
    t.equal(box:getTouching().floor, false, "not touching the floor")
  end)
end

test("destroying a body ends its contacts; the event holds the destroyed body", function()
  local world = level()
  local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  run(world, 10)
  box:destroy()
  local events = run(world, 1)
  t.equal(#events.ends, 1, "end events")
  t.truthy(events.ends[1].b == box, "the same userdata")
  t.equal(events.ends[1].b:isDestroyed(), true, "destroyed")
end)

test("a contact end names the destroyed body even after a new body took its slot", function()
  local world, floor = level()
  local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  run(world, 10)
  box:destroy()
  -- Created before the step: it takes the destroyed body's storage slot.
  local newcomer = world:newBody({x = 200, y = -5, hw = 5, hh = 5})
  t.equal(select(1, newcomer:getId()), select(1, box:getId()), "the same slot")
  local events = run(world, 1)
  t.equal(#events.ends, 1, "end events")
  t.truthy(events.ends[1].a == floor, "a: the floor")
  t.truthy(rawequal(events.ends[1].b, box), "b: the very userdata of the destroyed box")
  t.truthy(rawequal(world:getBodies()[2], newcomer), "the newcomer keeps its own userdata")
  run(world, 1)
  t.truthy(rawequal(world:getBodies()[2], newcomer), "still, after another step")
end)

test("touching flags: walls and ceiling relative to gravity", function()
  local world = level()
  -- Walls at x = +-20 (inner faces), a ceiling with its bottom face at y = -40.
  world:newBody({type = "static", x = 30, y = -50, hw = 10, hh = 50})
  world:newBody({type = "static", x = -30, y = -50, hw = 10, hh = 50})
  world:newBody({type = "static", x = 0, y = -50, hw = 20, hh = 10})
  local right = world:newBody({x = 10, y = -5, hw = 5, hh = 5, vx = 200})
  local left = world:newBody({x = -10, y = -5, hw = 5, hh = 5, vx = -200})
  local up = world:newBody({x = 0, y = -20, hw = 4, hh = 4, gravityScale = -1})
  run(world, 30)
  local r, l, u = right:getTouching(), left:getTouching(), up:getTouching()
  t.truthy(r.floor and r.wallRight and not r.wallLeft and not r.ceiling, "right box")
  t.truthy(l.floor and l.wallLeft and not l.wallRight and not l.ceiling, "left box")
  t.truthy(u.ceiling and not u.floor, "the box falling up")
end)

test("sensors report what enters and leaves them, and push nothing", function()
  local world = jostle.newWorld()
  local zone = world:newBody({type = "static", x = 100, y = 0, hw = 20, hh = 20, sensor = true})
  -- Moving right at 600/s: enters the zone (x from 75) and leaves it (x past 125).
  local visitor = world:newBody({x = 0, y = 0, hw = 5, hh = 5, vx = 600})
  local entered, left = nil, nil
  for step = 1, 30 do
    world:step(dt)
    for _, e in ipairs(world:getSensorBegins()) do
      t.truthy(e.sensor == zone and e.visitor == visitor, "begin pair")
      entered = entered or step
    end
    for _, e in ipairs(world:getSensorEnds()) do
      t.truthy(e.sensor == zone and e.visitor == visitor, "end pair")
      left = left or step
    end
  end
  -- x = 10 k after step k: overlapping from x > 75 (step 8) to x >= 125 (step 13).
  t.equal(entered, 8, "entered at step")
  t.equal(left, 13, "left at step")
  local _, vy = visitor:getVelocity()
  t.equal(select(1, visitor:getVelocity()), 600, "not slowed by the sensor")
  t.equal(vy, 0, "not pushed")
  t.equal(#world:getContactBegins(), 0, "sensors make no contact events")
end)

test("a box under a descending kinematic block is crushed once, stays put, and the crush ends", function()
  local world, floor = level()
  local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local block = world:newBody({type = "kinematic", x = 0, y = -40, hw = 30, hh = 10, vy = 60})
  local begins, ends = 0, 0
  for _ = 1, 120 do
    world:step(dt)
    for _, e in ipairs(world:getCrushBegins()) do
      t.truthy(e.body == box and e.by == block and e.against == floor, "the crush's bodies")
      begins = begins + 1
    end
    for _, e in ipairs(world:getCrushEnds()) do
      t.truthy(e.body == box and e.by == block, "the crush that ends")
      ends = ends + 1
    end
    t.truthy(select(2, box:getPosition()) <= -5 + 0.55, "never deeper in the floor than the crush depth")
  end
  t.near(select(2, box:getPosition()), -5, 0.051, "back on the floor")
  t.equal(begins, 1, "begins once")
  t.equal(ends, 1, "ends once")
end)

-- --- The pre-solve callback -----------------------------------------------------------

for _, solver in ipairs({"classic", "physical"}) do
  test(solver .. ": pre-solve sees the pair and can let it pass through", function()
    local world, floor = level(solver)
    local box = world:newBody({x = 0, y = -20, hw = 5, hh = 5})
    local calls = 0
    world:setPreSolve(function(c)
      calls = calls + 1
      t.truthy((c.a == floor and c.b == box) or (c.a == box and c.b == floor), "the pair")
      t.equal(c.nx, 0, "nx")
      t.equal(math.abs(c.ny), 1, "|ny|")
      t.equal(type(c.depth), "number", "depth")
      t.equal(c.bounce, 0, "bounce: max of the pair")
      t.equal(c.friction, 0.5, "friction: min of the pair")
      return false -- a ghost
    end)
    t.truthy(world:getPreSolve() ~= nil, "getPreSolve")
    run(world, 60)
    t.truthy(calls > 0, "called")
    local _, y = box:getPosition()
    t.truthy(y > 50, "fell through the floor (y = " .. y .. ")")
    -- Removed: the floor holds again.
    world:setPreSolve(nil)
    t.equal(world:getPreSolve(), nil, "removed")
    box:setPosition(0, -20)
    box:setVelocity(0, 0)
    run(world, 60)
    t.near(select(2, box:getPosition()), -5, 0.1, "resting on the floor")
  end)

  test(solver .. ": pre-solve can change the bounce of a pair", function()
    local world = level(solver)
    local box = world:newBody({x = 0, y = -105, hw = 5, hh = 5, bounce = 0})
    world:setPreSolve(function(c)
      c.bounce = 1
      -- returning nothing keeps the pair
    end)
    local rose = false
    for _ = 1, 60 do
      world:step(dt)
      local _, vy = box:getVelocity()
      if vy < -200 then rose = true end
    end
    t.truthy(rose, "bounced back up although both bodies have bounce 0")
  end)

  test(solver .. ": an error in pre-solve comes out of step; the world goes on", function()
    local world = level(solver)
    local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
    world:setPreSolve(function() error("boom in the callback") end)
    t.raises({"boom in the callback"}, world.step, world, dt)
    -- Any value, not only strings, arrives as it was raised.
    local raised = {code = 42}
    world:setPreSolve(function() error(raised) end)
    local ok, err = pcall(world.step, world, dt)
    t.equal(ok, false, "raised")
    t.truthy(rawequal(err, raised), "the very table raised")
    -- Bad values written back are errors too.
    world:setPreSolve(function(c) c.friction = "high" end)
    t.raises({"pre-solve: c.friction: expected a number, got string"}, world.step, world, dt)
    world:setPreSolve(function(c) c.bounce = 2 end)
    t.raises({"pre-solve: c.bounce: must be in [0, 1]"}, world.step, world, dt)
    world:setPreSolve(function(c) c.frcition = 0 end)
    t.raises({"pre-solve: c: unknown field \"frcition\" (did you mean \"friction\"?)"}, world.step, world, dt)
    -- The world steps again, and is not "inside a callback" any more.
    world:setPreSolve(nil)
    run(world, 30)
    t.near(select(2, box:getPosition()), -5, 0.1, "still resting on the floor")
  end)

  test(solver .. ": step and destroy from inside pre-solve are errors", function()
    local world = level(solver)
    world:newBody({x = 0, y = -5, hw = 5, hh = 5})
    local nested, destroyError
    world:setPreSolve(function()
      local ok, err = pcall(world.step, world, dt)
      nested = nested or (not ok and err)
      ok, err = pcall(world.destroy, world)
      destroyError = destroyError or (not ok and err)
    end)
    world:step(dt)
    t.truthy(nested and nested:find("World:step: called from a callback during step()", 1, true),
      "nested step: " .. tostring(nested))
    t.truthy(destroyError and destroyError:find("World:destroy: called from a callback", 1, true),
      "destroy: " .. tostring(destroyError))
    -- Unprotected, the nested step's error comes out of the outer step.
    world:setPreSolve(function() world:step(dt) end)
    t.raises({"called from a callback during step()"}, world.step, world, dt)
    world:setPreSolve(nil)
    world:step(dt)
  end)

  test(solver .. ": pre-solve may destroy and create bodies and query the world", function()
    local world, floor = level(solver)
    local box = world:newBody({x = 0, y = -20, hw = 5, hh = 5})
    local created
    world:setPreSolve(function(c)
      if c.a ~= box and c.b ~= box then return end
      t.equal(#world:queryPoint(0, 10), 1, "a query from the callback finds the floor")
      t.truthy(c.a == floor or c.b == floor, "the box meets the floor")
      box:destroy()
      created = world:newBody({x = 300, y = -100, hw = 5, hh = 5})
      return false
    end)
    run(world, 60)
    t.equal(box:isDestroyed(), true, "destroyed from the callback")
    t.truthy(created and not created:isDestroyed(), "created from the callback")
    t.equal(world:getBodyCount(), 2, "floor and the new body")
  end)
end

test("a pre-solve set from inside the callback applies from the next step", function()
  local world = level()
  world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local first, second = 0, 0
  local function secondCallback() second = second + 1 end
  world:setPreSolve(function()
    first = first + 1
    world:setPreSolve(secondCallback)
  end)
  world:step(dt)
  local firstCalls = first
  t.truthy(firstCalls >= 1 and second == 0, "the first callback ran the whole step")
  world:step(dt)
  t.equal(first, firstCalls, "the first is gone")
  t.truthy(second >= 1, "the second runs")
end)

test("an error in one world's callback leaves other worlds alone", function()
  local a = level()
  local b = level()
  a:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local inB = b:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local bCalls = 0
  b:setPreSolve(function() bCalls = bCalls + 1 end)
  -- a's callback steps b (allowed: another world), then fails.
  a:setPreSolve(function() b:step(dt); error("a fails") end)
  t.raises({"a fails"}, a.step, a, dt)
  t.truthy(bCalls >= 1, "b's callback ran inside a's")
  b:step(dt)
  t.near(select(2, inB:getPosition()), -5, 0.1, "b's box rests")
end)

test("callbacks inside coroutines", function()
  local world = level()
  world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local calls = 0
  world:setPreSolve(function() calls = calls + 1 end)
  local co = coroutine.create(function()
    world:step(dt)
    coroutine.yield("between steps")
    world:step(dt)
    return "done"
  end)
  t.equal(select(2, coroutine.resume(co)), "between steps", "first resume")
  t.equal(select(2, coroutine.resume(co)), "done", "second resume")
  t.truthy(calls >= 2, "called in both steps")
  -- Yielding from inside the callback cannot cross the C++ step: an error, not a crash.
  world:setPreSolve(function() coroutine.yield() end)
  local ok, err = coroutine.resume(coroutine.create(function() world:step(dt) end))
  t.equal(ok, false, "yield across the step fails")
  t.truthy(tostring(err):find("yield", 1, true), "a yield error: " .. tostring(err))
  world:setPreSolve(nil)
  world:step(dt)
end)

return t.run(tests)
