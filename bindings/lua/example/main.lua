-- The tutorial's demo on jostle: boxes of different bounce and friction fall onto
-- platforms. Click to drop a box, R to start again, M to switch between jostle's two
-- models (physical, the default; classic, the tutorial to the letter), Space to pause.
--
-- Run it from the repository, after building:   love bindings/lua/example
-- jostle.so is looked for next to this file, then through LUA_CPATH, then in the build
-- directory (build/lua/luajit/). docs/lua.md explains the ways to give it to LÖVE.
--
-- For tests: `love bindings/lua/example --seconds 3` simulates 3 seconds, prints a
-- summary line and quits (exit status 0 if every box landed, 1 if not); `--model classic`
-- starts in the classic model.

-- --- Finding jostle.so -------------------------------------------------------------------

-- LÖVE runs LuaJIT, so it needs the LuaJIT build of the module. LÖVE's own loader finds a
-- jostle.so copied next to main.lua; LUA_CPATH is honoured as by any Lua; and, when the
-- example is run from a source tree, the build directories are tried last.
local source = love.filesystem.getSource()
for _, dir in ipairs({"/../../../build/lua/luajit/", "/../../../../build/lua/luajit/"}) do
  package.cpath = package.cpath .. ";" .. source .. dir .. "?.so"
end
local found, jostle = pcall(require, "jostle")

-- --- The scene -----------------------------------------------------------------------------

-- The tutorial's scene (examples/scenes/tutorial.json): a floor, two walls, three
-- platforms, and boxes with the bounce and friction the tutorial plays with.
local statics = {
  {x = 400, y = 600, hw = 400, hh = 20, friction = 0.8},  -- floor
  {x = -10, y = 300, hw = 10, hh = 300, friction = 0},    -- left wall
  {x = 810, y = 300, hw = 10, hh = 300, friction = 0},    -- right wall
  {x = 200, y = 420, hw = 120, hh = 8, friction = 0.5},   -- low platform
  {x = 560, y = 300, hw = 110, hh = 8, friction = 0.5},   -- middle platform
  {x = 330, y = 180, hw = 70, hh = 8, friction = 0.5},    -- high platform
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

local world, clock
local solver = "physical"
local paused = false
-- What the game keeps about each box, keyed by the body itself: the same body is always
-- the same Lua value, so bodies make good table keys.
local info = {}
local simulated, frames = 0, 0
local stopAfter -- seconds of simulated time, from --seconds

local function addBox(def)
  local body = world:newBody({type = "dynamic", x = def.x, y = def.y, hw = def.hw, hh = def.hh,
    vx = def.vx, bounce = def.bounce, friction = def.friction})
  info[body] = {name = def.name, landed = false, flash = 0}
  return body
end

local function reset()
  world = jostle.newWorld({gravity = {0, 800}, maxVelocity = 1000, solver = solver})
  clock = jostle.newFixedStep(1 / 60)
  info = {}
  for _, def in ipairs(statics) do
    world:newBody({type = "static", x = def.x, y = def.y, hw = def.hw, hh = def.hh,
      friction = def.friction})
  end
  for _, def in ipairs(boxes) do
    addBox(def)
  end
end

-- --- LÖVE callbacks -------------------------------------------------------------------------

function love.load(args)
  for i = 1, #args do
    if args[i] == "--seconds" then
      stopAfter = tonumber(args[i + 1])
      assert(stopAfter and stopAfter > 0, "--seconds needs a number of seconds > 0")
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

-- After each step: boxes that began touching something are marked as landed and flash
-- in proportion to how hard they hit; the flash fades over a third of a second.
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
end

function love.update(dt)
  if not found or paused then
    return
  end
  -- A fixed step of 1/60 s whatever the frame rate; in a test, one step a frame, so that
  -- a slow machine (software rendering) simulates the same thing, only slower.
  local steps = stopAfter and 1 or clock:advance(dt)
  for _ = 1, steps do
    world:step(clock:getDt())
    simulated = simulated + clock:getDt()
    afterStep(clock:getDt())
  end
  frames = frames + 1

  if stopAfter and simulated >= stopAfter - 1e-9 then
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
    love.event.quit(landed == total and 0 or 1)
  end
end

-- Orange boxes, paler the more they bounce; grey statics; a flash of yellow on impact.
local function boxColour(body)
  local box = info[body]
  if not box then
    return 150 / 255, 150 / 255, 150 / 255
  end
  local bounce = body:getBounce()
  local r, g, b = 240 / 255, (150 + 80 * bounce) / 255, (60 + 150 * bounce) / 255
  local f = box.flash
  return r + (1 - r) * f, g + (0.9 - g) * f, b * (1 - f)
end

function love.draw()
  if not found then
    love.graphics.printf("jostle.so was not found.\n\n" .. tostring(jostle) ..
      "\n\nBuild it (cmake --build build) and copy build/lua/luajit/jostle.so next to " ..
      "main.lua, or set LUA_CPATH (docs/lua.md).", 40, 40, 720)
    return
  end
  for _, body in ipairs(world:getBodies()) do
    local x, y, w, h = body:getRect()
    local r, g, b = boxColour(body)
    love.graphics.setColor(r, g, b)
    love.graphics.rectangle("fill", x, y, w, h)
    -- A darker outline, and the friction as its thickness: sticky boxes look heavier.
    love.graphics.setColor(r * 0.6, g * 0.6, b * 0.6)
    love.graphics.setLineWidth(1 + 3 * body:getFriction())
    love.graphics.rectangle("line", x, y, w, h)
  end
  love.graphics.setColor(230 / 255, 230 / 255, 230 / 255)
  love.graphics.print(string.format("%s model   %d bodies   %s\n" ..
    "click: drop a box   R: reset   M: switch model   space: pause",
    solver, world:getBodyCount(), paused and "paused" or ""), 10, 10)
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
        info[body] = nil
        body:destroy()
      end
    end
  end
end

function love.keypressed(key)
  if key == "escape" then
    love.event.quit()
  elseif not found then
    return
  elseif key == "r" then
    reset()
  elseif key == "m" then
    solver = solver == "physical" and "classic" or "physical"
    reset()
  elseif key == "space" then
    paused = not paused
  end
end
