-- The tutorial's demo on jostle, with a player: boxes of different bounce and friction
-- fall onto platforms (the middle one a conveyor belt), and a character runs and jumps
-- among them, walks up two low steps, rides two lifts, jumps
-- up through a one-way platform and collects coins. Arrows (or A, D) walk, Up (or W)
-- jumps, Down + Up drops through the one-way platform; click to drop a box, right-click
-- to remove one, R to start again, M to switch between jostle's two models (physical, the
-- default; classic, the tutorial to the letter), I to draw the positions as they are
-- (read through LuaJIT's FFI) instead of between the last two steps, Tab to draw the
-- physics as jostle sees it over the game's own drawing (world:debugDraw), Space to pause.
--
-- Run it from the repository, after building:   love bindings/lua/example
-- jostle.so is looked for next to this file, then through LUA_CPATH, then in the build
-- directory (build/lua/luajit/). docs/lua.md explains the ways to give it to LÖVE.
--
-- For tests: `love bindings/lua/example --seconds 3` simulates 3 seconds, with the player
-- following a short script (walk right, jump), prints a summary and quits (exit status 0
-- if every box landed and the player walked and jumped as it should, 1 if not);
-- `--model classic` starts in the classic model; `--debug` starts with Tab's view on, and
-- the summary says how many shapes it drew in the last frame.

-- --- Finding jostle.so -------------------------------------------------------------------

-- LÖVE runs LuaJIT, so it needs the LuaJIT build of the module. LÖVE's own loader finds a
-- jostle.so copied next to main.lua; LUA_CPATH is honoured as by any Lua; and, when the
-- example is run from a source tree, the build directories are tried last.
local source = love.filesystem.getSource()
for _, dir in ipairs({"/../../../build/lua/luajit/", "/../../../../build/lua/luajit/"}) do
  package.cpath = package.cpath .. ";" .. source .. dir .. "?.so"
end
local found, jostle = pcall(require, "jostle")
local ffi = require("ffi") -- LÖVE runs LuaJIT: its FFI reads getPositionsBuffer

-- --- The scene -----------------------------------------------------------------------------

-- The tutorial's scene (examples/scenes/tutorial.json): a floor, two walls, three
-- platforms, and boxes with the bounce and friction the tutorial plays with.
local statics = {
  {x = 400, y = 600, hw = 400, hh = 20, friction = 0.8},  -- floor, its top at y = 580
  {x = -10, y = 300, hw = 10, hh = 300, friction = 0},    -- left wall
  {x = 810, y = 300, hw = 10, hh = 300, friction = 0},    -- right wall
  {x = 200, y = 420, hw = 120, hh = 8, friction = 0.5},   -- low platform
  -- the middle platform, x 450 .. 670: a conveyor belt carrying what rests on it left
  {x = 560, y = 300, hw = 110, hh = 8, friction = 0.5, surfaceVelocity = {-40, 0}},
  {x = 330, y = 180, hw = 70, hh = 8, friction = 0.5},    -- high platform
  -- Two low steps by the right wall, 10 high each: the player walks up them.
  {x = 755, y = 575, hw = 15, hh = 5, friction = 0.8},
  {x = 785, y = 570, hw = 15, hh = 10, friction = 0.8},
}
local boxes = {
  {name = "crate", x = 180, y = 40, hw = 20, hh = 20, bounce = 0, friction = 0.8},
  {name = "bouncer", x = 230, y = 0, hw = 8, hh = 8, bounce = 0.8, friction = 0.2},
  {name = "plank", x = 560, y = 60, hw = 40, hh = 6, bounce = 0.1, friction = 1},
  {name = "ice", x = 520, y = 20, hw = 12, hh = 12, vx = 120, bounce = 0, friction = 0},
  {name = "rubber", x = 600, y = -20, hw = 10, hh = 14, bounce = 0.6, friction = 0.9},
  {name = "brick", x = 330, y = 40, hw = 16, hh = 10, bounce = 0.2, friction = 0.5},
  {name = "pebble", x = 340, y = -40, hw = 5, hh = 5, vx = -60, bounce = 0.4, friction = 0.3},
  {name = "tower", x = 700, y = 100, hw = 8, hh = 30, bounce = 0, friction = 0.6},
  {name = "slider", x = 80, y = 200, hw = 14, hh = 14, vx = 200, bounce = 0.3, friction = 0.1},
}

-- What the example adds for the player: a one-way platform by the left wall (its top 80
-- above the floor: a jump goes up through it), a lift shuttling sideways under the middle
-- platform, one going up and down beside it (its top from 40 above the floor, a jump up,
-- with room under it for the player, to the middle platform's top, y = 292), and coins,
-- one at a time, at these places in turn.
local oneWayDef = {type = "static", x = 40, y = 504, hw = 30, hh = 4, oneWay = {0, -1}}
local sideLiftDef = {type = "kinematic", x = 380, y = 496, hw = 32, hh = 6}
local SIDE_LEFT, SIDE_RIGHT = 380, 620
local upLiftDef = {type = "kinematic", x = 700, y = 544, hw = 28, hh = 6}
local UP_BOTTOM, UP_TOP = 544, 298
local coinSpots = {{560, 250}, {40, 450}, {500, 440}, {330, 130}}

local G, SPEED, JUMP = 800, 150, 420

local world, clock
local solver = "physical"
local paused, interpolate = false, true
local debugView = false -- Tab: world:debugDraw over the game's own drawing
local drawnShapes = 0 -- by it, in the last frame
-- What the game keeps about each body, keyed by the body itself (the same body is always
-- the same Lua value, so bodies make good table keys): its look, and for boxes whether it
-- landed and how bright it flashes.
local info, look = {}, {}
local player, oneWay, sideLift, upLift, coin
local upState, upWait, coins, coinSpot
local bodies, positions -- world:getBodies(), kept until a body comes or goes; reused table
local jumpQueued = false
local simulated, frames = 0, 0
local stopAfter -- seconds of simulated time, from --seconds
local check -- what the test run measures of the player

local function newBody(def, colour)
  local body = world:newBody(def)
  look[body] = {hw = def.hw, hh = def.hh, colour = colour}
  bodies = nil
  return body
end

local function addBox(def)
  local body = newBody({type = "dynamic", x = def.x, y = def.y, hw = def.hw, hh = def.hh,
    vx = def.vx, bounce = def.bounce, friction = def.friction})
  info[body] = {name = def.name, landed = false, flash = 0}
  -- Orange boxes, paler the more they bounce; thicker outlines the more they rub.
  local bounce = def.bounce or 0
  look[body].colour = {240 / 255, (150 + 80 * bounce) / 255, (60 + 150 * bounce) / 255}
  look[body].line = 1 + 3 * (def.friction or 0.5)
  return body
end

local function reset()
  world = jostle.newWorld({gravity = {0, G}, maxVelocity = 1000, solver = solver})
  clock = jostle.newFixedStep(1 / 60)
  info, look = {}, {}
  for _, def in ipairs(statics) do
    newBody({type = "static", x = def.x, y = def.y, hw = def.hw, hh = def.hh,
      friction = def.friction, surfaceVelocity = def.surfaceVelocity},
      {150 / 255, 150 / 255, 150 / 255})
  end
  for _, def in ipairs(boxes) do
    addBox(def)
  end
  oneWay = newBody(oneWayDef, {120 / 255, 150 / 255, 190 / 255})
  sideLift = newBody(sideLiftDef, {110 / 255, 190 / 255, 120 / 255})
  sideLift:setVelocity(60, 0)
  upLift = newBody(upLiftDef, {110 / 255, 190 / 255, 120 / 255})
  upState, upWait = "bottom", 60
  coins, coinSpot = 0, 1
  coin = newBody({type = "static", x = coinSpots[1][1], y = coinSpots[1][2], hw = 6, hh = 6,
    sensor = true}, {1, 215 / 255, 0})
  -- The player: a character, 16 x 28, standing on the floor by the left wall. It slips
  -- round a platform's corner its jump clips by up to 4 px, and walks up steps 10 high.
  player = newBody({x = 100, y = 566, hw = 8, hh = 14, character = true,
    cornerCorrection = 4, stepUp = 10}, {90 / 255, 160 / 255, 1})
  check = {minWalk = math.huge, maxWalk = -math.huge, startY = 566, highest = 0}
end

-- --- One step of the game --------------------------------------------------------------

-- The player's input for this step: the keyboard's, or in a test run a short script: stand
-- for half a second, walk right for a second, jump, walk on.
local function input()
  if stopAfter then
    local walking = simulated >= 0.5
    local jump = math.abs(simulated - 1.5) < 1e-6
    return walking and 1 or 0, jump, false
  end
  local right = love.keyboard.isDown("right", "d") and 1 or 0
  local left = love.keyboard.isDown("left", "a") and 1 or 0
  local jump = jumpQueued
  jumpQueued = false
  return right - left, jump, love.keyboard.isDown("down", "s")
end

-- The player, as a game commands a character: the walk speed from the input every step,
-- a jump by an impulse when it stands on something, down + jump drops through.
local function controlPlayer()
  local move, jump, down = input()
  player:setWalkSpeed(move * SPEED)
  if jump and player:getGround() then
    if down then
      player:dropThrough(0.25)
    else
      player:applyImpulse(0, -JUMP * player:getMass())
    end
  end
end

-- The sideways lift shuttles at 60; the other waits a second, rises at 60, waits, sinks.
-- (60 is 1 a step: both reach their ends exactly.)
local function controlLifts()
  local x = sideLift:getPosition()
  local vx = sideLift:getVelocity()
  if vx > 0 and x >= SIDE_RIGHT - 1e-3 then sideLift:setVelocity(-60, 0) end
  if vx < 0 and x <= SIDE_LEFT + 1e-3 then sideLift:setVelocity(60, 0) end
  local _, y = upLift:getPosition()
  if upState == "bottom" or upState == "top" then
    upWait = upWait - 1
    if upWait <= 0 then
      upState = upState == "bottom" and "rising" or "sinking"
      upLift:setVelocity(0, upState == "rising" and -60 or 60)
    end
  elseif (upState == "rising" and y <= UP_TOP + 1e-3)
    or (upState == "sinking" and y >= UP_BOTTOM - 1e-3) then
    upState, upWait = upState == "rising" and "top" or "bottom", 60
    upLift:setVelocity(0, 0)
  end
end

-- After each step: boxes that began touching something are marked as landed and flash
-- in proportion to how hard they hit; the flash fades over a third of a second. The coin
-- is collected when the player enters it, and moves to its next place.
local function afterStep(dt)
  for _, box in pairs(info) do
    box.flash = math.max(0, box.flash - dt * 3)
  end
  for _, contact in ipairs(world:getContactBegins()) do
    for _, body in ipairs({contact.a, contact.b}) do
      local box = info[body]
      if box then
        box.landed = true
        box.flash = math.min(1, contact.approachSpeed / 600)
      end
    end
  end
  for _, e in ipairs(world:getSensorBegins()) do
    if e.sensor == coin and e.visitor == player then
      coins = coins + 1
      coinSpot = coinSpot % #coinSpots + 1
      coin:setPosition(coinSpots[coinSpot][1], coinSpots[coinSpot][2])
    end
  end
end

-- In a test run: the player's speed while it walks on the floor, and how high it jumps.
local function measure()
  local _, y = player:getPosition()
  if simulated > 1.5 and simulated < 2.5 then
    check.highest = math.max(check.highest, check.startY - y)
  end
  local vx = player:getVelocity()
  if simulated > 0.55 and simulated < 1.45 and player:getGround() then
    check.minWalk = math.min(check.minWalk, vx)
    check.maxWalk = math.max(check.maxWalk, vx)
  end
end

-- --- LÖVE callbacks -------------------------------------------------------------------------

function love.load(args)
  for i = 1, #args do
    if args[i] == "--seconds" then
      stopAfter = tonumber(args[i + 1])
      assert(stopAfter and stopAfter > 0, "--seconds needs a number of seconds > 0")
    elseif args[i] == "--debug" then
      debugView = true
    elseif args[i] == "--model" then
      solver = args[i + 1]
      assert(solver == "physical" or solver == "classic", "--model: physical or classic")
    end
  end
  if not found then
    -- Say what is missing, in the window and on the terminal.
    print("jostle example: cannot load jostle.so:\n" .. tostring(jostle))
    if stopAfter then
      love.event.quit(1)
    end
    return
  end
  love.graphics.setBackgroundColor(24 / 255, 26 / 255, 33 / 255)
  reset()
end

local function summary()
  local total, landed, resting = 0, 0, 0
  for body, box in pairs(info) do
    total = total + 1
    if box.landed then landed = landed + 1 end
    local _, vy = body:getVelocity()
    if math.abs(vy) < 1 then resting = resting + 1 end
  end
  print(string.format("jostle example: %.2f s simulated in %d frames, %s model, %d bodies; "
    .. "%d of %d boxes landed, %d resting", simulated, frames, solver, world:getBodyCount(),
    landed, total, resting))
  -- A jump of 420 under g = 800 in steps of 1/60 s rises
  -- (31 x 420 - 13.33 x 31 x 32 / 2) / 60 = 106.78.
  print(string.format("jostle example: the player walked at %.1f to %.1f and jumped %.2f high",
    check.minWalk, check.maxWalk, check.highest))
  if debugView then
    print(string.format("jostle example: debug drawing drew %d shapes for %d bodies",
      drawnShapes, world:getBodyCount()))
  end
  local walked = check.minWalk == SPEED and check.maxWalk == SPEED
  local jumped = math.abs(check.highest - 106.78) < 0.01
  return landed == total and walked and jumped
end

function love.update(dt)
  if not found or paused then
    return
  end
  -- A fixed step of 1/60 s whatever the frame rate; in a test, one step a frame, so that
  -- a slow machine (software rendering) simulates the same thing, only slower. The clock
  -- keeps where the bodies were before the frame's last step, to draw between the two.
  local steps = stopAfter and 1 or clock:advance(dt)
  for i = 1, steps do
    controlPlayer()
    controlLifts()
    if i == steps then clock:rememberPositions(world) end
    world:step(clock:getDt())
    simulated = simulated + clock:getDt()
    afterStep(clock:getDt())
    measure()
  end
  frames = frames + 1

  if stopAfter and simulated >= stopAfter - 1e-9 then
    love.event.quit(summary() and 0 or 1)
  end
end

function love.keypressed(key)
  if key == "escape" then
    love.event.quit()
  elseif not found then
    return
  elseif key == "up" or key == "w" then
    jumpQueued = true
  elseif key == "r" then
    reset()
  elseif key == "m" then
    solver = solver == "physical" and "classic" or "physical"
    reset()
  elseif key == "i" then
    interpolate = not interpolate
  elseif key == "tab" then
    debugView = not debugView
  elseif key == "space" then
    paused = not paused
  end
end

-- --- The physics as jostle sees it (Tab) -----------------------------------------------------

-- world:debugDraw calls these with what to draw, in world units (pixels here) and colours
-- 0xRRGGBBAA; jostle.rgba gives LÖVE's 0-to-1 parts. Fills are see-through, so that the
-- game's own drawing shows under them. Shapes drawn in the last frame are counted for
-- --debug's summary (drawnShapes).
local function fillWith(colour)
  local r, g, b, a = jostle.rgba(colour)
  love.graphics.setColor(r, g, b, a * 0.35)
end
local function outlineWith(colour)
  love.graphics.setColor(jostle.rgba(colour))
end
local debugDrawer = {
  line = function(x1, y1, x2, y2, colour)
    outlineWith(colour)
    love.graphics.line(x1, y1, x2, y2)
  end,
  box = function(x, y, hw, hh, fill, outline)
    drawnShapes = drawnShapes + 1
    if fill % 256 ~= 0 then
      fillWith(fill)
      love.graphics.rectangle("fill", x - hw, y - hh, 2 * hw, 2 * hh)
    end
    outlineWith(outline)
    love.graphics.rectangle("line", x - hw, y - hh, 2 * hw, 2 * hh)
  end,
  roundedBox = function(x, y, hw, hh, radius, fill, outline)
    drawnShapes = drawnShapes + 1
    if fill % 256 ~= 0 then
      fillWith(fill)
      love.graphics.rectangle("fill", x - hw, y - hh, 2 * hw, 2 * hh, radius, radius)
    end
    outlineWith(outline)
    love.graphics.rectangle("line", x - hw, y - hh, 2 * hw, 2 * hh, radius, radius)
  end,
  triangle = function(x1, y1, x2, y2, x3, y3, fill, outline)
    drawnShapes = drawnShapes + 1
    if fill % 256 ~= 0 then
      fillWith(fill)
      love.graphics.polygon("fill", x1, y1, x2, y2, x3, y3)
    end
    outlineWith(outline)
    love.graphics.polygon("line", x1, y1, x2, y2, x3, y3)
  end,
  point = function(x, y, size, colour)
    outlineWith(colour)
    love.graphics.rectangle("fill", x - 1.5, y - 1.5, 3, 3)
  end,
}
local debugOptions = {contacts = true, velocities = true, touching = true, markLength = 12}

-- Every body is drawn from one read of the whole world: between its last two steps
-- (clock:getDrawPositions, into a table reused frame after frame), or as it is now,
-- straight from the world's float array (getPositionsBuffer, through the FFI). No call
-- per body: sizes and colours are the game's own, kept when the bodies were made.
function love.draw()
  if not found then
    love.graphics.printf("jostle.so was not found.\n\n" .. tostring(jostle) ..
      "\n\nBuild it (cmake --build build) and copy build/lua/luajit/jostle.so next to " ..
      "main.lua, or set LUA_CPATH (docs/lua.md).", 40, 40, 720)
    return
  end
  bodies = bodies or world:getBodies()
  local at, base
  if interpolate then
    positions = clock:getDrawPositions(world, positions)
    at, base = positions, 1
  else
    at, base = ffi.cast("float*", (world:getPositionsBuffer())), 0
  end
  for i, body in ipairs(bodies) do
    local x, y = at[base + 2 * (i - 1)], at[base + 2 * (i - 1) + 1]
    local l = look[body]
    local r, g, b = unpack(l.colour)
    local box = info[body]
    if box then -- a flash of yellow on impact
      local f = box.flash
      r, g, b = r + (1 - r) * f, g + (0.9 - g) * f, b * (1 - f)
    end
    love.graphics.setColor(r, g, b)
    love.graphics.rectangle("fill", x - l.hw, y - l.hh, 2 * l.hw, 2 * l.hh)
    love.graphics.setColor(r * 0.6, g * 0.6, b * 0.6)
    love.graphics.setLineWidth(l.line or 1)
    love.graphics.rectangle("line", x - l.hw, y - l.hh, 2 * l.hw, 2 * l.hh)
  end
  if debugView then
    drawnShapes = 0
    love.graphics.setLineWidth(1)
    world:debugDraw(debugDrawer, debugOptions)
  end
  love.graphics.setColor(230 / 255, 230 / 255, 230 / 255)
  love.graphics.print(string.format("%s model   %d bodies   coins %d   %s%s\n" ..
    "arrows: walk   up: jump   down+up: drop through   click: drop a box   R: reset   " ..
    "M: switch model   I: interpolation   tab: physics   space: pause", solver, world:getBodyCount(), coins,
    interpolate and "interpolated" or "as stepped (FFI buffer)", paused and "   paused" or ""),
    10, 10)
end

function love.mousepressed(x, y, button)
  if not found then
    return
  end
  if button == 1 then
    -- A box of random size, bounce and friction, unless the spot is taken.
    local half = love.math.random(6, 18)
    if #world:queryBox(x, y, half, half) == 0 then
      addBox({name = "dropped", x = x, y = y, hw = half, hh = half,
        bounce = love.math.random(0, 8) / 10, friction = love.math.random(0, 10) / 10})
    end
  elseif button == 2 then
    -- Right click removes the box under the mouse.
    for _, body in ipairs(world:queryPoint(x, y)) do
      if info[body] then
        info[body], look[body] = nil, nil
        body:destroy()
        bodies = nil
      end
    end
  end
end
