-- Characters (walk speed, wall friction, ground), forces and impulses, and the contacts a
-- body has now, as tests/test_characters.cpp and tests/test_forces.cpp check them in C++.
local jostle = require("jostle")
local t = require("helper")

local g, dt = 800, 1 / 60

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- A floor whose top is at y = 0 (y grows downward), 10,000 wide.
local function level(solver, gravity)
  local world = jostle.newWorld({gravity = {0, gravity or g}, solver = solver, sleeping = false})
  local floor = world:newBody({type = "static", x = 0, y = 50, hw = 5000, hh = 50})
  return world, floor
end

test("character and wallFriction: in the definition, getDef, and their setters", function()
  local world = jostle.newWorld()
  local hero = world:newBody({x = 0, y = 0, hw = 6, hh = 8, character = true, wallFriction = 0.25})
  t.equal(hero:isCharacter(), true, "isCharacter")
  t.equal(hero:getWallFriction(), 0.25, "getWallFriction")
  local def = hero:getDef()
  t.equal(def.character, true, "getDef().character")
  t.equal(def.wallFriction, 0.25, "getDef().wallFriction")
  local copy = world:newBody(def)
  t.equal(copy:isCharacter(), true, "a copy is a character")
  t.equal(copy:getWallFriction(), 0.25, "with the same wall friction")
  -- The defaults.
  local crate = world:newBody({x = 50, y = 0, hw = 5, hh = 5})
  t.equal(crate:isCharacter(), false, "not a character by default")
  t.equal(crate:getWallFriction(), 0, "wall friction 0 by default")
  t.equal(crate:getWalkSpeed(), 0, "walk speed 0 by default")
  -- Setters, read back.
  hero:setCharacter(false)
  t.equal(hero:isCharacter(), false, "setCharacter(false)")
  hero:setWallFriction(0.5)
  t.equal(hero:getWallFriction(), 0.5, "setWallFriction")
  t.raises({"Body:setWalkSpeed", "the body is not a character"}, hero.setWalkSpeed, hero, -120)
  hero:setCharacter(true)
  hero:setWalkSpeed(-120)
  t.equal(hero:getWalkSpeed(), -120, "setWalkSpeed")
  t.raises({"Body:setWallFriction", "friction"}, hero.setWallFriction, hero, 1.5)
  t.raises({"Body:setWalkSpeed", "speed: must be a finite number"}, hero.setWalkSpeed, hero, 0 / 0)
  t.raises({"Body:setCharacter", "character: expected true or false"}, hero.setCharacter, hero, 1)
  t.raises({"World:newBody", "wallFriction"}, world.newBody, world,
    {x = 0, y = 0, hw = 1, hh = 1, wallFriction = -1})
end)

for _, solver in ipairs({"classic", "physical"}) do
  test(solver .. ": a character walking at 150 reads back 150, every step", function()
    local world = level(solver)
    local hero = world:newBody({x = 0, y = -8, hw = 6, hh = 8, character = true})
    t.steps(world, 10) -- settle
    hero:setWalkSpeed(150)
    for i = 1, 30 do
      world:step(dt)
      t.equal((hero:getVelocity()), 150, "vx at step " .. i)
    end
    -- 30 steps of 150 / 60 = 2.5: 75 along.
    t.near((hero:getPosition()), 75, 1e-3, "x")
  end)
end

test("physical: an ordinary body set to 150 every frame reads back 150 - mu g dt", function()
  -- Friction (0.5, the default of both) takes mu g dt = 0.5 x 800 / 60 = 6.667 a step:
  -- what a character is for.
  local world = level("physical")
  local box = world:newBody({x = 0, y = -8, hw = 6, hh = 8})
  t.steps(world, 10)
  for _ = 1, 10 do
    box:setVelocity(150, select(2, box:getVelocity()))
    world:step(dt)
  end
  t.near((box:getVelocity()), 150 - 0.5 * g * dt, 1e-3, "vx")
end)

-- A lift 80 x 12 with its top at y = 0 and a character on it, in the middle.
local function liftScene(solver)
  local world = jostle.newWorld({gravity = {0, g}, solver = solver, sleeping = false})
  local lift = world:newBody({type = "kinematic", x = 0, y = 6, hw = 40, hh = 6})
  local hero = world:newBody({x = 0, y = -8, hw = 6, hh = 8, character = true})
  t.steps(world, 10)
  return world, lift, hero
end

for _, solver in ipairs({"classic", "physical"}) do
  test(solver .. ": getGround: the lift, its push and its velocity; nil in the air", function()
    local world, lift, hero = liftScene(solver)
    lift:setVelocity(30, -20)
    world:step(dt)
    local ground, nx, ny, vx, vy = hero:getGround()
    t.truthy(ground == lift, "the ground is the lift")
    t.equal(nx, 0, "nx")
    t.equal(ny, -1, "ny: the lift pushes up")
    t.equal(vx, 30, "the lift's vx")
    t.equal(vy, -20, "the lift's vy")
    -- A jump: two steps later, in the air.
    hero:setVelocity(0, -400)
    world:step(dt)
    world:step(dt)
    t.equal(hero:getGround(), nil, "in the air")
    t.equal(select("#", hero:getGround()), 1, "one nil, not five")
    t.equal(lift:getGround(), nil, "the lift stands on nothing")
  end)

  test(solver .. ": a character standing on a lift moving sideways keeps its place", function()
    local world, lift, hero = liftScene(solver)
    local function offset()
      local hx, hy = hero:getPosition()
      local lx, ly = lift:getPosition()
      return hx - lx, hy - ly
    end
    local x0, y0 = offset()
    for _, leg in ipairs({60, 0, -60, -120, 0, 45}) do
      lift:setVelocity(leg, 0)
      for _ = 1, 30 do
        hero:setWalkSpeed(0)
        world:step(dt)
        local x, y = offset()
        t.near(x, x0, 1e-3, "x on the lift, leg " .. leg)
        t.near(y, y0, 0.2, "y on the lift, leg " .. leg)
      end
    end
  end)

  test(solver .. ": a force acts for one step as F / m dt; an impulse at once as I / m", function()
    local world = jostle.newWorld({gravity = {0, 0}, solver = solver, sleeping = false})
    -- 20 x 10, density 2: mass 400. (800, -400) / 400 / 60 = (1/30, -1/60).
    local box = world:newBody({x = 0, y = 0, hw = 10, hh = 5, density = 2})
    box:applyForce(800, -400)
    t.equal(box:getVelocity(), 0, "nothing before the step")
    world:step(dt)
    local vx, vy = box:getVelocity()
    t.near(vx, 1 / 30, 1e-7, "vx")
    t.near(vy, -1 / 60, 1e-7, "vy")
    world:step(dt)
    t.near((box:getVelocity()), 1 / 30, 1e-7, "the next step: no force left")
    -- Applied before every step, forces add up: 60 steps of (200 + 200) / 400 = 1/s^2
    -- more: after a second, 1 faster.
    for _ = 1, 60 do
      box:applyForce(200, 0)
      box:applyForce(200, 0)
      world:step(dt)
    end
    t.near((box:getVelocity()), 1 / 30 + 1, 1e-5, "a lasting force")
    -- Mass 4: an impulse of (8, -2) is (2, -0.5) at once.
    local ball = world:newBody({x = 100, y = 0, hw = 1, hh = 1, mass = 4})
    ball:applyImpulse(8, -2)
    vx, vy = ball:getVelocity()
    t.equal(vx, 2, "impulse vx")
    t.equal(vy, -0.5, "impulse vy")
    -- Static and kinematic bodies are infinitely heavy.
    local wall = world:newBody({type = "static", x = -100, y = 0, hw = 5, hh = 5})
    local lift = world:newBody({type = "kinematic", x = -200, y = 0, hw = 5, hh = 5})
    for _, body in ipairs({wall, lift}) do
      body:applyForce(1e6, 0)
      body:applyImpulse(1e6, 0)
    end
    world:step(dt)
    t.equal(wall:getVelocity(), 0, "the wall")
    t.equal(lift:getVelocity(), 0, "the lift")
    t.raises({"Body:applyForce", "fx: must be a finite number"}, box.applyForce, box, 0 / 0, 0)
    t.raises({"Body:applyImpulse", "iy: expected a number, got no value"}, box.applyImpulse, box, 1)
  end)

  test(solver .. ": getContacts of a crate on a floor: the floor, normal, point, impulse",
    function()
      -- A 10 x 10 crate (mass 100) resting on a floor whose top is y = 0, under g = 600,
      -- from x = 20 to 30; another one at x = -50; the floor from -100 to 100.
      local world = jostle.newWorld({gravity = {0, 600}, solver = solver, sleeping = false})
      local floor = world:newBody({type = "static", x = 0, y = 10, hw = 100, hh = 10})
      local crate = world:newBody({x = 25, y = -5, hw = 5, hh = 5})
      local other = world:newBody({x = -50, y = -5, hw = 5, hh = 5})
      t.steps(world, 30)
      local contacts = crate:getContacts()
      t.equal(#contacts, 1, "one contact")
      local c = contacts[1]
      t.truthy(c.other == floor, "with the floor")
      t.equal(c.nx, 0, "nx")
      t.equal(c.ny, -1, "ny: from the floor towards the crate")
      -- The middle of the stretch they share, x from 20 to 30; y between the faces.
      t.near(c.x, 25, 1e-4, "x")
      t.near(c.y, 0, 0.05, "y")
      if solver == "physical" then
        -- Holding it up for a step: m g dt = 100 x 600 / 60 = 1000.
        t.near(c.impulse, 1000, 1, "impulse")
      end
      local ofFloor = floor:getContacts()
      t.equal(#ofFloor, 2, "the floor touches both")
      t.truthy(ofFloor[1].other == crate, "in the order of the bodies: the crate first")
      t.equal(ofFloor[1].ny, 1, "from the crate towards the floor")
      t.truthy(ofFloor[2].other == other, "then the other")
      t.equal(crate:isTouching(floor), true, "crate, floor")
      t.equal(floor:isTouching(crate), true, "floor, crate")
      t.equal(crate:isTouching(other), false, "crate, other")
      t.raises({"Body:isTouching", "other: expected a Body, got no value"}, crate.isTouching, crate)
      local elsewhere = jostle.newWorld():newBody({x = 0, y = 0, hw = 1, hh = 1})
      t.raises({"Body:isTouching", "other: the body belongs to another world"}, crate.isTouching,
        crate, elsewhere)
    end)

  test(solver .. ": a contact begin says where the bodies met; an end has no point", function()
    local world = jostle.newWorld({gravity = {0, 600}, solver = solver, sleeping = false})
    world:newBody({type = "static", x = 0, y = 10, hw = 100, hh = 10})
    -- 20 x 10, overhanging the floor's left end (-100): it shares x from -100 to -85.
    local box = world:newBody({x = -95, y = -50, hw = 10, hh = 5})
    -- The first event `get` reports in n steps.
    local function first(get, n)
      local event
      for _ = 1, n do
        world:step(dt)
        event = event or get(world)[1]
      end
      return event
    end
    local begin = first(world.getContactBegins, 60)
    t.truthy(begin, "it landed")
    t.near(begin.x, -92.5, 1e-3, "x: the middle of -100 .. -85")
    t.near(begin.y, 0, 0.05, "y: on the floor's top")
    box:setVelocity(0, -500)
    local ended = first(world.getContactEnds, 10)
    t.truthy(ended, "it left")
    t.equal(ended.x, nil, "no x in an end")
    t.equal(ended.y, nil, "no y in an end")
  end)
end

test("a character jumping while pressed into a wall rises as in open air", function()
  -- The issue's case: holding right against a wall and jumping. sqrt(2 g 99): 99 high.
  local jump = math.sqrt(2 * g * 99)
  local function rise(withWall)
    local world = level("physical")
    if withWall then
      world:newBody({type = "static", x = 150, y = -200, hw = 50, hh = 200}) -- left face 100
    end
    local hero = world:newBody({x = 94, y = -8, hw = 6, hh = 8, character = true})
    hero:setWalkSpeed(150)
    t.steps(world, 10)
    hero:setVelocity(0, -jump)
    local _, start = hero:getPosition()
    local highest = 0
    for _ = 1, 60 do
      world:step(dt)
      highest = math.max(highest, start - select(2, hero:getPosition()))
    end
    return highest
  end
  local open, walled = rise(false), rise(true)
  t.truthy(open > 90, "open air: " .. open)
  t.near(walled, open, 0.01 * open, "against the wall")
end)

test("a conveyor carries what stands on it; a character walks relative to it", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local belt = world:newBody({type = "static", x = 0, y = 50, hw = 5000, hh = 50,
                              surfaceVelocity = {-70, 0}})
  local hero = world:newBody({x = 0, y = -8, hw = 6, hh = 8, character = true})
  for _ = 1, 10 do world:step(1 / 60) end
  t.near(select(1, hero:getVelocity()), -70, 1e-3, "carried at the belt's speed")
  hero:setWalkSpeed(70)
  for _ = 1, 3 do world:step(1 / 60) end
  t.near(select(1, hero:getVelocity()), 0, 1e-3, "walking against it, in place")
  t.equal(select(1, belt:getSurfaceVelocity()), -70, "getSurfaceVelocity")
  belt:setSurfaceVelocity(0, 0)
  t.raises({"Body:setSurfaceVelocity", "static or kinematic"}, hero.setSurfaceVelocity, hero, 1, 0)
  t.raises({"World:newBody", "surfaceVelocity"}, world.newBody, world,
    {x = 0, y = 0, hw = 1, hh = 1, surfaceVelocity = {1, 0}})
end)

return t.run(tests)
