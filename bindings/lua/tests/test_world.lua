-- The world and its bodies: creation, stepping, settings, identity, lifetime.
local jostle = require("jostle")
local t = require("helper")

local g, dt = 800, 1 / 60

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

test("the issue's example runs and the box lands on the floor", function()
  local world = jostle.newWorld({gravity = {0, 800}})
  local floor = world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10})
  local box = world:newBody({type = "dynamic", x = 0, y = 0, hw = 10, hh = 10, bounce = 0.5})
  world:step(1 / 60)
  local x, y = box:getPosition()
  local vx, vy = box:getVelocity()
  t.equal(x, 0, "x")
  t.equal(vx, 0, "vx")
  -- One step of semi-implicit Euler: v = g dt, then y = v dt.
  t.near(vy, g * dt, 1e-4, "vy")
  t.near(y, g * dt * dt, 1e-5, "y")
  t.equal(floor:getType(), "static", "type")
  t.equal(type(jostle.version), "string", "jostle.version")
end)

-- v_k = k g dt and y_n = sum of v_k dt = g dt^2 n (n + 1) / 2: the core integrates the
-- velocity first, then the position with the new velocity (semi-implicit Euler).
for _, solver in ipairs({"classic", "physical"}) do
  test(solver .. ": a falling box follows y = g dt^2 n (n + 1) / 2", function()
    local world = jostle.newWorld({gravity = {0, g}, solver = solver})
    local box = world:newBody({x = 5, y = 0, hw = 10, hh = 10})
    for n = 1, 40 do
      world:step(dt)
      local x, y = box:getPosition()
      local _, vy = box:getVelocity()
      t.equal(x, 5, "x")
      -- float arithmetic in the core: a relative error of a few float epsilons
      local expected = g * dt * dt * n * (n + 1) / 2
      t.near(y, expected, 1e-5 * expected + 1e-5, "y after step " .. n)
      t.near(vy, g * dt * n, 1e-5 * g * dt * n, "vy after step " .. n)
    end
  end)

  test(solver .. ": the box comes to rest on the floor at floor top - hh", function()
    local world = jostle.newWorld({gravity = {0, g}, solver = solver})
    world:newBody({type = "static", x = 0, y = 300, hw = 400, hh = 10}) -- top at 290
    local box = world:newBody({x = 0, y = 0, hw = 10, hh = 10})
    t.steps(world, 120)
    local _, y = box:getPosition()
    -- The physical model leaves at most its slop (1% of the half extent) of overlap.
    t.near(y, 290 - 10, 0.01 * 10 + 1e-4, "resting y")
    local _, vy = box:getVelocity()
    t.near(vy, 0, g * dt + 1e-3, "resting vy")
    local _, sy = box:getSeparation()
    t.truthy(sy <= 0, "the floor pushed it up (separation y <= 0)")
    t.truthy(box:getTouching().floor, "touching the floor")
  end)
end

test("a dropped box rebounds to e^2 h (physical)", function()
  -- The impact speed v = sqrt(2 g h) comes back as e v, which climbs e^2 h; the discrete
  -- step errs by at most one step of travel, v dt (as tests/test_physical.cpp derives).
  local h, e, fine = 200, 0.5, 1 / 240
  local world = jostle.newWorld({gravity = {0, g}})
  world:newBody({type = "static", x = 0, y = 50, hw = 1000, hh = 50}) -- top at y = 0
  local box = world:newBody({x = 0, y = -h - 5, hw = 5, hh = 5, bounce = e})
  local bounced, apex = false, 0
  for _ = 1, 100000 do
    world:step(fine)
    local _, vy = box:getVelocity()
    if vy < 0 then bounced = true end
    if bounced then
      local _, y = box:getPosition()
      apex = math.max(apex, -(y + 5))
      if vy >= 0 then break end
    end
  end
  t.truthy(bounced, "bounced")
  t.near(apex, e * e * h, math.sqrt(2 * g * h) * fine, "rebound height")
end)

test("the same body is the same userdata: == and table keys work", function()
  local world = jostle.newWorld()
  local a = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  local b = world:newBody({x = 5, y = 0, hw = 1, hh = 1})
  local bodies = world:getBodies()
  t.equal(#bodies, 2, "#getBodies()")
  t.truthy(rawequal(bodies[1], a) and rawequal(bodies[2], b), "getBodies returns a and b themselves")
  local names = {[a] = "a", [b] = "b"}
  t.equal(names[world:queryPoint(5, 0)[1]], "b", "a query's body finds the table entry")
  t.equal(world:getBodyCount(), 2, "getBodyCount")
  t.truthy(a:getWorld() == world, "getWorld")
  -- A body whose userdata was collected comes back as a new userdata of the same body.
  local index, generation, serial = b:getId()
  b, bodies, names = nil, nil, nil
  collectgarbage()
  collectgarbage()
  local again = world:getBodies()[2]
  local index2, generation2, serial2 = again:getId()
  t.equal(index2, index, "slot")
  t.equal(generation2, generation, "generation")
  t.equal(serial2, serial, "world")
  t.equal(again:getPosition(), 5, "x of the body found again")
end)

test("a destroyed body's slot reused by a new body: the old userdata stays destroyed", function()
  local world = jostle.newWorld()
  local old = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  old:destroy()
  local new = world:newBody({x = 7, y = 0, hw = 1, hh = 1})
  t.truthy(old ~= new, "a different userdata")
  t.truthy(old:isDestroyed(), "old is destroyed")
  t.truthy(not new:isDestroyed(), "new is live")
  t.equal(world:getBodies()[1], new, "getBodies gives the new one")
  t.equal(world:getBodyCount(), 1, "count")
end)

test("bodies of two worlds in the same slot, at the same generation, are told apart", function()
  local first, second = jostle.newWorld(), jostle.newWorld()
  local a = first:newBody({x = 0, y = 0, hw = 1, hh = 1})
  local b = second:newBody({x = 5, y = 0, hw = 1, hh = 1})
  local indexA, generationA, worldA = a:getId()
  local indexB, generationB, worldB = b:getId()
  t.truthy(indexA == indexB and generationA == generationB, "the same slot and generation")
  t.truthy(worldA ~= worldB, "different worlds")
  t.truthy(a ~= b, "different bodies")
  t.raises({"Body:isTouching", "other: the body belongs to another world"}, a.isTouching, a, b)
  t.truthy(first:getBodies()[1] == a and second:getBodies()[1] == b, "each world gives its own")
  t.equal(first:queryPoint(0, 0)[1], a, "a query of the first world")
  t.equal(second:queryPoint(5, 0)[1], b, "a query of the second world")
end)

test("a world lives as long as one of its bodies", function()
  local box
  do
    local world = jostle.newWorld({gravity = {0, g}})
    box = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  end
  collectgarbage()
  collectgarbage()
  local world = box:getWorld()
  world:step(dt)
  local _, y = box:getPosition()
  t.near(y, g * dt * dt, 1e-5, "y after a step of the world found again")
end)

test("getDef round trip: newBody(body:getDef()) makes the same body", function()
  local world = jostle.newWorld()
  local def = {type = "kinematic", x = 1, y = 2, hw = 3, hh = 4, vx = 5, vy = 6, bounce = 0.25,
    friction = 0.75, mass = 9, gravityScale = -1, damping = 0.5, bullet = true,
    oneWay = {0, -1}, category = 4, mask = 0xFFFFFFFE, sensor = true}
  local body = world:newBody(def)
  local got = body:getDef()
  for k, v in pairs(def) do
    if k == "oneWay" then
      t.equal(got.oneWay[1], 0, "oneWay[1]")
      t.equal(got.oneWay[2], -1, "oneWay[2]")
    else
      t.equal(got[k], v, k)
    end
  end
  t.equal(got.density, nil, "density is left out when mass is set")
  local copy = world:newBody(got)
  local again = copy:getDef()
  for k, v in pairs(got) do
    if type(v) == "table" then -- a vector: oneWay, slope
      t.equal(again[k][1], v[1], "copy " .. k .. "[1]")
      t.equal(again[k][2], v[2], "copy " .. k .. "[2]")
    else
      t.equal(again[k], v, "copy " .. k)
    end
  end
  -- Without a mass, the density is given back.
  local light = world:newBody({x = 0, y = 0, hw = 1, hh = 2, density = 3})
  t.equal(light:getDef().density, 3, "density")
  t.equal(light:getDef().mass, nil, "no mass")
  t.equal(light:getMass(), 3 * 4 * 1 * 2, "mass = density x area")
  t.equal(light:getDensity(), 3, "getDensity")
end)

test("getDef carries userData: newBody(body:getDef()) keeps it", function()
  local world = jostle.newWorld()
  local item = {name = "coin", value = 10}
  local coin = world:newBody({type = "static", x = 5, y = 6, hw = 4, hh = 4, sensor = true,
    userData = item})
  local def = coin:getDef()
  t.truthy(def.userData == item, "getDef gives the user data itself (the same table)")
  local copy = world:newBody(def)
  t.truthy(copy:getUserData() == item, "the copy has the same user data")
  -- Set afterwards, cleared, and given as a value that is not a table.
  coin:setUserData("picked")
  t.equal(coin:getDef().userData, "picked", "user data set by setUserData")
  coin:setUserData(nil)
  t.equal(coin:getDef().userData, nil, "no user data: no field")
  t.equal(world:newBody(coin:getDef()):getUserData(), nil, "and none in a copy")
  -- A new body in a destroyed body's slot does not inherit its user data.
  copy:destroy()
  local plain = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  t.equal(plain:getDef().userData, nil, "a reused slot has none")
end)

test("every setter is read back by its getter", function()
  local world = jostle.newWorld({gravity = {0, g}})
  local body = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  body:setPosition(3, 4)
  t.equal(select(2, body:getPosition()), 4, "position")
  body:setVelocity(-1, 2)
  t.equal(body:getVelocity(), -1, "velocity")
  body:setHalfExtents(5, 6)
  local hw, hh = body:getHalfExtents()
  t.equal(hw + hh, 11, "half extents")
  local left, top, width, height = body:getRect()
  t.equal(left, 3 - 5, "rect left")
  t.equal(top, 4 - 6, "rect top")
  t.equal(width, 10, "rect width")
  t.equal(height, 12, "rect height")
  body:setBounce(0.5)
  t.equal(body:getBounce(), 0.5, "bounce")
  body:setFriction(0.25)
  t.equal(body:getFriction(), 0.25, "friction")
  body:setMass(3)
  t.equal(body:getMass(), 3, "mass")
  body:setDensity(2)
  t.equal(body:getMass(), 2 * 4 * 5 * 6, "mass from density")
  body:setGravityScale(0)
  t.equal(body:getGravityScale(), 0, "gravity scale")
  body:setDamping(1.5)
  t.equal(body:getDamping(), 1.5, "damping")
  body:setBullet(true)
  t.equal(body:isBullet(), true, "bullet")
  body:setSensor(true)
  t.equal(body:isSensor(), true, "sensor")
  body:setSensor(false)
  body:setOneWay(0, -1)
  local nx, ny = body:getOneWay()
  t.equal(nx, 0, "oneWay x")
  t.equal(ny, -1, "oneWay y")
  body:dropThrough(0.5)
  body:setCategory(8)
  t.equal(body:getCategory(), 8, "category")
  body:setMask(0xFFFFFFFF)
  t.equal(body:getMask(), 4294967295, "mask")
  body:setType("static")
  t.equal(body:getType(), "static", "type")
  t.equal(body:getMass(), math.huge, "a static body is infinitely heavy")
  body:setType("dynamic")
  body:wake()
  t.equal(body:isAwake(), true, "awake")
  body:setUserData({hp = 3})
  t.equal(body:getUserData().hp, 3, "user data")
  body:setUserData(nil)
  t.equal(body:getUserData(), nil, "user data cleared")
  t.truthy(tostring(body):find("jostle.Body", 1, true), "tostring")
end)

test("user data: given in the definition, and not inherited by a reused slot", function()
  local world = jostle.newWorld()
  local player = world:newBody({x = 0, y = 0, hw = 1, hh = 1, userData = "player"})
  t.equal(player:getUserData(), "player", "from the definition")
  player:destroy()
  local crate = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  t.equal(crate:getUserData(), nil, "the new body in the same slot has none")
end)

test("world settings: gravity, maxVelocity, solver, sleeping, options", function()
  local world = jostle.newWorld({gravity = {1, 2}, maxVelocity = 500, solver = "classic",
    classic = {mass = true}, physical = {velocityIterations = 8, frictionMix = "geometricMean"},
    sleeping = false})
  local gx, gy = world:getGravity()
  t.equal(gx + gy, 3, "gravity")
  t.equal(world:getMaxVelocity(), 500, "maxVelocity")
  t.equal(world:getSolver(), "classic", "solver")
  t.equal(world:getSleeping(), false, "sleeping")
  local classic = world:getClassicOptions()
  t.truthy(classic.mass and not classic.coulomb and not classic.ccd, "classic options")
  -- Only the fields given change.
  world:setClassicOptions({coulomb = true})
  classic = world:getClassicOptions()
  t.truthy(classic.mass and classic.coulomb, "classic options after a partial set")
  local physical = world:getPhysicalOptions()
  t.equal(physical.velocityIterations, 8, "velocityIterations")
  t.equal(physical.positionIterations, 3, "positionIterations default")
  t.equal(physical.frictionMix, "geometricMean", "frictionMix")
  world:setPhysicalOptions({slop = 0.02})
  t.near(world:getPhysicalOptions().slop, 0.02, 1e-7, "slop")
  t.equal(world:getPhysicalOptions().velocityIterations, 8, "untouched by a partial set")
  world:setGravity(0, 800)
  t.equal(select(2, world:getGravity()), 800, "setGravity")
  world:setMaxVelocity(math.huge)
  t.equal(world:getMaxVelocity(), math.huge, "no clamp")
  world:setSolver("physical")
  t.equal(world:getSolver(), "physical", "setSolver")
  world:setSleeping(true)
  t.equal(world:getSleeping(), true, "setSleeping")
  -- The defaults of an empty definition are those of C++'s WorldDef.
  local default = jostle.newWorld()
  t.equal(default:getSolver(), "physical", "default solver")
  t.equal(default:getMaxVelocity(), math.huge, "default maxVelocity")
  t.equal(default:getSleeping(), true, "default sleeping")
  t.equal(default:getPhysicalOptions().maxContactsPerBody, 64, "default contact budget")
end)

-- Threads change nothing: 3,000 boxes (the step's loops cut into blocks) land the same
-- way on one worker and on two.
test("a world stepped on two workers gives the same positions as on one", function()
  local function crowd(workers)
    local world = jostle.newWorld({gravity = {0, 800}, workers = workers})
    world:newBody({type = "static", x = 600, y = 1000, hw = 1000, hh = 10})
    local boxes = {}
    for i = 0, 2999 do
      boxes[#boxes + 1] = world:newBody({x = (i % 100) * 12, y = math.floor(i / 100) * 12, hw = 5, hh = 5,
                                         vx = (i % 7) * 10 - 30})
    end
    for _ = 1, 30 do world:step(1 / 60) end
    return world, boxes
  end
  local one, a = crowd(1)
  local two, b = crowd(2)
  t.equal(one:getWorkers(), 1, "one worker by default")
  t.equal(two:getWorkers(), 2, "two workers")
  local p, stages = two:getProfile(), 0
  for _, name in ipairs({"riders", "velocities", "pairs", "corners", "contacts", "support",
                         "impacts", "layers", "solve", "shock", "bounces", "sweeps", "positions",
                         "correction", "snap", "store", "events", "sleep"}) do
    t.truthy(p[name] >= 0, "profile." .. name)
    stages = stages + p[name]
  end
  t.truthy(p.step > 0 and stages <= p.step * 1.001, "the stages are laps within the step")
  for i = 1, #a do
    local x1, y1 = a[i]:getPosition()
    local x2, y2 = b[i]:getPosition()
    if x1 ~= x2 or y1 ~= y2 then t.equal(x2 .. "," .. y2, x1 .. "," .. y1, "box " .. i) end
  end
  t.raises({"jostle.newWorld", "workers: must be"}, function() jostle.newWorld({workers = 0}) end)
  t.raises({"jostle.newWorld", "workers: must be"}, function() jostle.newWorld({workers = 65}) end)
end)

-- Each dynamic body has a budget of contacts per step (maxContactsPerBody): boxes dropped
-- at one spot make n (n - 1) / 2 pairs, of which a budget of 4 keeps at most 2 per box.
test("a pile at one spot keeps to the contact budget and says what it left out", function()
  local world = jostle.newWorld({gravity = {0, 10}, physical = {maxContactsPerBody = 4}})
  world:newBody({type = "static", x = 0, y = 1, hw = 100, hh = 1})
  for _ = 1, 30 do world:newBody({x = 0, y = -0.5, hw = 0.5, hh = 0.5}) end
  world:step(1 / 60)
  -- 435 pairs among the boxes; each box takes part in at most 4: at most 30 * 4 / 2 kept.
  t.truthy(world:getPairsLeftOut() >= 435 - 60, "pairs left out: " .. world:getPairsLeftOut())
  local quiet = jostle.newWorld({gravity = {0, 10}})
  quiet:newBody({type = "static", x = 0, y = 1, hw = 100, hh = 1})
  quiet:newBody({x = 0, y = -0.5, hw = 0.5, hh = 0.5})
  quiet:step(1 / 60)
  t.equal(quiet:getPairsLeftOut(), 0, "a sane scene leaves nothing out")
  t.raises({"World:setPhysicalOptions", "maxContactsPerBody: must be from 1 to 65536"},
    function() world:setPhysicalOptions({maxContactsPerBody = 0}) end)
end)

test("maxVelocity clamps a falling body's speed", function()
  local world = jostle.newWorld({gravity = {0, g}, maxVelocity = 100})
  local box = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  t.steps(world, 60)
  local _, vy = box:getVelocity()
  t.near(vy, 100, 1e-3, "clamped speed")
end)

test("a body at rest falls asleep and a kinematic body carries on at its velocity", function()
  local world = jostle.newWorld({gravity = {0, g}})
  world:newBody({type = "static", x = 0, y = 50, hw = 100, hh = 50})
  local box = world:newBody({x = 0, y = -5, hw = 5, hh = 5})
  local lift = world:newBody({type = "kinematic", x = 500, y = 0, hw = 5, hh = 5, vx = 60})
  t.steps(world, 120)
  t.equal(box:isAwake(), false, "asleep after two seconds at rest")
  t.near(lift:getPosition(), 500 + 60 * 2, 1e-2, "kinematic x after 2 s")
end)

test("world:destroy frees it; its bodies then raise", function()
  local world = jostle.newWorld()
  local body = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  world:destroy()
  t.equal(world:isDestroyed(), true, "isDestroyed")
  world:destroy() -- twice is harmless
  t.raises({"World:step", "the world was destroyed"}, world.step, world, dt)
  t.raises({"Body:getPosition", "world was destroyed"}, body.getPosition, body)
  t.equal(body:isDestroyed(), true, "the body of a destroyed world is destroyed")
  t.truthy(tostring(world):find("destroyed", 1, true), "tostring says destroyed")
end)

return t.run(tests)
