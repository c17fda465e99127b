-- The fixed-step helper: steps from frame times, the cap, alpha, and update.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

test("three frames of 1/180 s are one step of 1/60 s", function()
  local clock = jostle.newFixedStep(1 / 60)
  t.equal(clock:advance(1 / 180), 0, "frame 1")
  t.equal(clock:advance(1 / 180), 0, "frame 2")
  t.equal(clock:advance(1 / 180), 1, "frame 3")
  t.near(clock:getDt(), 1 / 60, 1e-9, "dt")
  t.equal(clock:getMaxStepsPerFrame(), 8, "the default cap")
end)

test("alpha: how far the left-over time reaches towards the next step", function()
  local clock = jostle.newFixedStep(1 / 60)
  t.equal(clock:advance(1 / 120), 0, "half a step")
  t.near(clock:getAlpha(), 0.5, 1e-6, "alpha")
  t.equal(clock:advance(1 / 120), 1, "the other half")
  t.near(clock:getAlpha(), 0, 1e-3, "alpha after the step")
  clock:advance(1 / 120)
  clock:reset()
  t.equal(clock:getAlpha(), 0, "reset forgets the time left over")
end)

test("the cap: a long frame takes at most maxStepsPerFrame steps", function()
  local clock = jostle.newFixedStep(1 / 60, 4)
  t.equal(clock:advance(1), 4, "a one-second frame")
  -- 60 steps were due: the 56 beyond the cap are dropped.
  t.near(clock:getDroppedSeconds(), 56 / 60, 1e-6, "dropped")
  t.equal(clock:advance(1 / 60), 1, "back to normal")
  t.equal(clock:getDroppedSeconds(), 0, "nothing dropped")
end)

test("update steps the world exactly as stepping it by hand does", function()
  local function newWorld()
    local world = jostle.newWorld({gravity = {0, 800}})
    world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
    return world, world:newBody({x = 0, y = 0, hw = 10, hh = 10, vx = 30})
  end
  local a, boxA = newWorld()
  local b, boxB = newWorld()
  local clock = jostle.newFixedStep(1 / 60)
  local total = 0
  -- Uneven frames, 0.08 s every five, 125 of them: 2 s, 120 steps in all.
  local frames = {0.01, 0.02, 0.005, 0.03, 0.015}
  for i = 1, 125 do
    total = total + clock:update(a, frames[(i - 1) % #frames + 1])
  end
  t.equal(total, 120, "steps taken")
  for _ = 1, total do b:step(1 / 60) end
  local ax, ay = boxA:getPosition()
  local bx, by = boxB:getPosition()
  t.equal(ax, bx, "x, bit for bit")
  t.equal(ay, by, "y, bit for bit")
end)

test("an error in a step stops update and comes out of it", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
  world:newBody({x = 0, y = 280, hw = 10, hh = 10})
  world:setPreSolve(function() error("callback failed") end)
  local clock = jostle.newFixedStep(1 / 60)
  t.raises({"callback failed"}, clock.update, clock, world, 0.1)
  world:setPreSolve(nil)
  t.equal(clock:update(world, 1 / 60), 1, "works again")
  t.truthy(tostring(clock):find("jostle.FixedStep", 1, true), "tostring")
end)

test("the pending time, saved and put back, gives the same steps to come", function()
  local clock, copy = jostle.newFixedStep(0.25), jostle.newFixedStep(0.25)
  for _ = 1, 3 do clock:advance(0.125) end
  t.equal(clock:getPendingNanoseconds(), 125000000, "three frames of 1/8 s, a step of 1/4 s")
  copy:setPendingNanoseconds(clock:getPendingNanoseconds())
  for _, frame in ipairs({0.1, 0.17, 0.33, 0.05}) do
    t.equal(copy:advance(frame), clock:advance(frame), "frame " .. frame)
  end
  t.raises({"FixedStep:setPendingNanoseconds", "nanoseconds must be from -250000 to 249749999"},
           copy.setPendingNanoseconds, copy, 250000000)
end)

test("update's afterStep hands the game each step's events, not only the last step's", function()
  -- Boxes landing in the first, third and sixth of a frame's eight steps (fallen
  -- g dt^2 n (n + 1) / 2 after n steps: gaps of 0.1, 1 and 4.5 close in steps 1, 3 and 6).
  local function landings(eachStep)
    local world = jostle.newWorld({gravity = {0, 1000}})
    world:newBody({type = "static", x = 0, y = 10, hw = 100, hh = 10})
    for _, gap in ipairs({0.1, 1, 4.5}) do
      world:newBody({x = 10 * gap, y = -1 - gap, hw = 1, hh = 1})
    end
    local clock, begins = jostle.newFixedStep(1 / 60, 8), 0
    if eachStep then
      t.equal(clock:update(world, 8 / 60, function() begins = begins + #world:getContactBegins() end),
              8, "eight steps")
    else
      clock:update(world, 8 / 60)
      begins = #world:getContactBegins()
    end
    return begins
  end
  t.equal(landings(true), 3, "every landing, read after each step")
  t.truthy(landings(false) < 3, "the last step's landings alone, read after the frame")
  local clock, world = jostle.newFixedStep(1 / 60), jostle.newWorld()
  t.raises({"FixedStep:update", "afterStep: expected a function, got number"},
           clock.update, clock, world, 1 / 60, 5)
  t.raises({"afterStep failed"}, clock.update, clock, world, 1 / 60, function() error("afterStep failed") end)
end)

test("reset forgets where bodies were: a restored world is drawn where it is", function()
  local world = jostle.newWorld({gravity = {0, 0}})
  local box = world:newBody({hw = 1, hh = 1, vx = 4})
  local start = world:snapshot()
  local clock = jostle.newFixedStep(0.25)
  clock:update(world, 0.25)
  clock:update(world, 0.375) -- from 1 to 2, alpha 0.5
  world:restore(start)
  t.near((clock:getDrawPosition(world, box)), 0.5, 1e-6, "between 1 (before the step) and 0")
  clock:reset()
  t.equal((clock:getDrawPosition(world, box)), 0, "drawn where it is")
end)

return t.run(tests)
