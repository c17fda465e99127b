-- A scripted player runs a level, as a game would play it: a tile map with walls and a
-- ledge, a one-way platform with a coin above it, a lift that shuttles sideways over a
-- pit, one that goes up and down a shaft, and crates. The player is a dynamic body with
-- `character = true`, driven frame by frame by a script of inputs (left, right, jump,
-- down + jump), and its code is what a game would write, with no workaround: the walk
-- speed from the input every frame, jumps by an impulse from the ground, drop-through,
-- getGround to know it stands on something, sensor events for the coin. No pre-solve, no
-- platform velocity added by hand, no query under the feet. Each stage checks where the
-- player is. A second player, a kinematic body moved with world:move, fetches the coin too.
--
-- TRACE=1 prints every frame.
local jostle = require("jostle")
local t = require("helper")

local g, dt = 800, 1 / 60
local SPEED, JUMP = 150, 420
local HW, HH = 6, 12 -- the player: 12 x 24
local trace = os.getenv("TRACE")

-- The level, 64 x 18 tiles of 16 (column c from x = 16 c, row r from y = 16 r: y grows
-- downward). The floor's top is
-- y = 256; a ledge 48 high from x 256 to 352 (its top y = 208); a pit from x 544 to 704,
-- which the sideways lift crosses; the vertical lift's shaft from x 800 to 864; a shelf
-- whose top is y = 160 from x 864 to the right wall, at x 1008.
local ROWS = {
  "#..............................................................#", -- 0
  "#..............................................................#", -- 1
  "#..............................................................#", -- 2
  "#..............................................................#", -- 3
  "#..............................................................#", -- 4
  "#..............................................................#", -- 5
  "#..............................................................#", -- 6
  "#..............................................................#", -- 7
  "#..............................................................#", -- 8
  "#..............................................................#", -- 9
  "#.....................................................##########", -- 10
  "#.....................................................##########", -- 11
  "#.....................................................##########", -- 12
  "#...............######................................##########", -- 13
  "#...............######................................##########", -- 14
  "#...............######................................##########", -- 15
  "##################################..........######....##########", -- 16
  "##################################..........######....##########", -- 17
}

local FLOOR, LEDGE_TOP, LEDGE_LEFT, SHELF_TOP = 256, 208, 256, 160
local RIGHT_WALL = 1008
-- The sideways lift (64 wide) shuttles between these centres, 1 from either side of the pit.
local LIFT_LEFT, LIFT_RIGHT = 544 + 33, 704 - 33

-- A jump of v0 = 420 under g = 800 in steps of 1/60 s: the velocity after step k is
-- 420 - k g dt (g dt = 13.33), upwards for k <= 31, so the body rises
-- sum_{k=1}^{31} (420 - 13.33 k) dt = (31 x 420 - 13.33 x 31 x 32 / 2) / 60 = 106.78.
local APEX = (31 * JUMP - g * dt * 31 * 32 / 2) * dt

local function newLevel()
  local world = jostle.newWorld({gravity = {0, g}})
  local level = {world = world}
  level.map = world:newTileMap({x = 0, y = 0, tile = 16, rows = ROWS})
  -- A one-way platform from x 400 to 496, its top 64 above the floor; the coin above it.
  level.oneWay = world:newBody({type = "static", x = 448, y = 196, hw = 48, hh = 4,
    oneWay = {0, -1}})
  level.coin = world:newBody({type = "static", x = 448, y = 150, hw = 6, hh = 6, sensor = true})
  -- Two crates by the start, 16 x 16 each, light enough to push: the player's feet grip
  -- 0.5 x its 192 x g, the two crates rub 0.5 x 2 x 64 x g on the floor.
  level.crates = {world:newBody({x = 56, y = 248, hw = 8, hh = 8, density = 0.25}),
    world:newBody({x = 72, y = 248, hw = 8, hh = 8, density = 0.25})}
  -- The sideways lift, 64 x 12, its top flush with the floor, waiting at the pit's left
  -- end; the vertical lift, 60 x 12, in the shaft, its top from the floor's (256) up to
  -- the shelf's (160).
  level.sideLift = world:newBody({type = "kinematic", x = LIFT_LEFT, y = 262, hw = 32, hh = 6})
  level.upLift = world:newBody({type = "kinematic", x = 832, y = 262, hw = 30, hh = 6})
  return level
end

-- --- The game's code -------------------------------------------------------------------

-- The player, from the input of one frame: {move = -1, 0 or 1, jump = pressed this frame,
-- down = held}.
local function controlPlayer(player, input)
  player:setWalkSpeed(input.move * SPEED)
  if input.jump and player:getGround() then
    if input.down then
      player:dropThrough(0.25)
    else
      player:applyImpulse(0, -JUMP * player:getMass())
    end
  end
end

-- The lifts: the sideways one waits at the left end until someone stands on it, then
-- shuttles at 60; the vertical one rises at 60 when someone stands on it at the bottom,
-- waits at the top, sinks back, and so on.
local function newLiftController(level, rider)
  local side, up = level.sideLift, level.upLift
  local sideStarted, upState, upWait = false, "bottom", 0
  return function()
    if not sideStarted and rider:getGround() == side then
      sideStarted = true
      side:setVelocity(60, 0)
    end
    if sideStarted then
      local x = side:getPosition()
      local vx = side:getVelocity()
      if vx > 0 and x >= LIFT_RIGHT - 1e-3 then side:setVelocity(-60, 0) end
      if vx < 0 and x <= LIFT_LEFT + 1e-3 then side:setVelocity(60, 0) end
    end
    local _, y = up:getPosition()
    if upState == "bottom" and rider:getGround() == up then
      upState = "rising"
      up:setVelocity(0, -60)
    elseif upState == "rising" and y <= 166 + 1e-3 then
      upState, upWait = "top", 30
      up:setVelocity(0, 0)
    elseif upState == "top" then
      upWait = upWait - 1
      if upWait == 0 then
        upState = "sinking"
        up:setVelocity(0, 60)
      end
    elseif upState == "sinking" and y >= 262 - 1e-3 then
      upState = "rising"
      up:setVelocity(0, -60)
    end
  end
end

-- --- The script --------------------------------------------------------------------------

-- Runs the level with the player, stage by stage. A stage holds an input until its
-- condition `done` is met (at most `frames` frames: else the test fails), calling `each` after
-- every step; a jump is pressed on a stage's first frame.
local function newRun(level, player, control)
  local run = {frame = 0, coins = 0}
  local lifts = newLiftController(level, player)
  function run.stage(name, stage)
    local input = {move = stage.move or 0, down = stage.down, jump = stage.jump}
    for i = 1, stage.frames do
      control(player, input)
      input.jump = false
      lifts()
      level.world:step(dt)
      run.frame = run.frame + 1
      for _, e in ipairs(level.world:getSensorBegins()) do
        if e.sensor == level.coin and e.visitor == player then
          run.coins = run.coins + 1
          run.coinFrame = run.frame
        end
      end
      if trace then
        local x, y = player:getPosition()
        local vx, vy = player:getVelocity()
        local ground = player:getGround()
        print(string.format("%-28s %4d  x %9.4f y %9.4f  vx %9.4f vy %9.4f  %s", name, i, x, y,
          vx, vy, ground and tostring(ground) or "air"))
      end
      if stage.each then stage.each(i) end
      if stage.done and stage.done(i) then return i end
    end
    if stage.done then
      error(name .. ": not done after " .. stage.frames .. " frames", 2)
    end
    return stage.frames
  end
  return run
end

local function px(body) return (body:getPosition()) end
local function py(body) return select(2, body:getPosition()) end

local function onGround(player, what)
  local ground = player:getGround()
  if type(what) == "function" then return ground ~= nil and what(ground) end
  return ground == what
end

-- A check for every frame of a ride: the rider's place on the lift is where it was when
-- the check was made (x within 1e-3, y within 0.2), and it stands on the lift.
local function riding(rider, lift, what)
  local ox, oy = px(rider) - px(lift), py(rider) - py(lift)
  return function(i)
    t.near(px(rider) - px(lift), ox, 1e-3, "x on " .. what .. ", frame " .. i)
    t.near(py(rider) - py(lift), oy, 0.2, "y on " .. what .. ", frame " .. i)
    t.truthy(onGround(rider, lift), "on " .. what .. ", frame " .. i)
  end
end

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

test("a character runs the level", function()
  local level = newLevel()
  local world, map = level.world, level.map
  local player = world:newBody({x = 120, y = FLOOR - HH, hw = HW, hh = HH, character = true})
  local run = newRun(level, player, controlPlayer)
  local function onMap(ground) return ground:getTileMap() == map end

  -- 1. Settle, then push the two crates left until they are against the left wall
  --    (x = 16): the first crate's centre at 16 + 8, the second's at 40, the player
  --    against it at 48 + 6 = 54.
  run.stage("settle", {frames = 10})
  t.truthy(onGround(player, onMap), "standing on the floor")
  local c1, c2 = level.crates[1], level.crates[2]
  run.stage("push the crates left", {move = -1, frames = 90})
  t.near(px(c1), 24, 0.15, "crate 1 against the wall")
  t.near(px(c2), 40, 0.25, "crate 2 against crate 1")
  t.near(px(player), 54, 0.35, "the player against crate 2")
  t.equal(player:isTouching(c2), true, "touching crate 2")
  t.equal(c2:isTouching(c1), true, "the crates touch")
  t.near(py(c1), FLOOR - 8, 0.05, "crate 1 still on the floor")

  -- 2. Walk right to the ledge's face: 150 every frame (the crates stay behind).
  run.stage("walk to the ledge", {move = 1, frames = 120, each = function(i)
    if i > 3 and not player:getTouching().wallRight then
      t.equal((player:getVelocity()), SPEED, "walking at 150, frame " .. i)
    end
  end, done = function() return player:getTouching().wallRight end})
  t.near(px(player), LEDGE_LEFT - HW, 0.05, "against the ledge's face")

  -- 3. Jump while pressed into the ledge's face: the player rises along it as in open
  --    air (no wall friction: APEX, within 0.01), clears the corner without catching on
  --    it (from the frame its bottom is above the ledge's top, it moves right
  --    150 dt = 2.5 every frame, and no wall is touched), and lands on the ledge, its top
  --    at 208. Right is let go of over the ledge (x 300), so as to come down on it.
  t.equal(select(2, player:getVelocity()), 0, "at rest before the jump")
  local startY = py(player)
  local highest, cleared, lastX = 0, nil, px(player)
  local function rise() highest = math.max(highest, startY - py(player)) end
  run.stage("jump onto the ledge", {move = 1, jump = true, frames = 60, each = function(i)
    rise()
    local x = px(player)
    if py(player) + HH < LEDGE_TOP - 0.01 and not cleared then cleared = i end
    if cleared and i > cleared then
      t.near(x - lastX, SPEED * dt, 1e-3, "no catch on the corner, frame " .. i)
      t.equal(player:getTouching().wallRight, false, "no wall at the corner, frame " .. i)
    end
    lastX = x
  end, done = function() return px(player) >= 300 end})
  t.truthy(cleared, "the bottom went above the ledge's top")
  run.stage("come down on the ledge", {frames = 60, each = rise, done = function()
    return onGround(player, onMap)
  end})
  t.near(highest, APEX, 0.01, "rose as in open air")
  t.near(py(player), LEDGE_TOP - HH, 0.05, "on the ledge")
  t.near(px(player), 300, 0.01, "where right was let go of")

  -- 4. Walk off the ledge's far end and on, under the one-way platform (x 400 .. 496).
  run.stage("walk under the one-way", {move = 1, frames = 120, done = function()
    return px(player) >= 448 and onGround(player, onMap)
  end})
  t.near(py(player), FLOOR - HH, 0.05, "down on the floor")
  run.stage("stop", {frames = 3})

  -- 5. Jump straight up through the one-way platform, through the coin (a sensor: the
  --    game counts it from the sensor event and takes it away), and land on the
  --    platform's top, y = 192.
  run.stage("jump through the one-way", {jump = true, frames = 90, done = function(i)
    if run.coins > 0 and not level.coin:isDestroyed() then level.coin:destroy() end
    return i > 5 and onGround(player, level.oneWay)
  end})
  t.equal(run.coins, 1, "picked up the coin")
  t.equal(level.coin:isDestroyed(), true, "the coin is gone")
  t.near(py(player), 192 - HH, 0.05, "standing on the one-way platform")
  local ground, nx, ny = player:getGround()
  t.truthy(ground == level.oneWay and nx == 0 and ny == -1, "getGround: the platform, pushing up")

  -- 6. Down + jump: through the platform, back to the floor.
  run.stage("drop through", {down = true, jump = true, frames = 60, done = function(i)
    return i > 2 and onGround(player, onMap)
  end})
  t.near(py(player), FLOOR - HH, 0.05, "back on the floor")

  -- 7. The sideways lift: walk to it (it waits at the pit's left end, from x 545 to 609),
  --    step on it, stand (it starts when someone stands on it); it carries the player to
  --    the right end (x 671) and back, the player's place on it never moving.
  local lift = level.sideLift
  run.stage("walk onto the sideways lift", {move = 1, frames = 120, done = function()
    return onGround(player, lift) and px(player) >= px(lift) - 16
  end})
  local function offset()
    return px(player) - px(lift), py(player) - py(lift)
  end
  run.stage("settle on the lift", {frames = 1})
  t.near(select(2, offset()), -6 - HH, 0.05, "on the lift's top")
  local ride = riding(player, lift, "the lift")
  local rideStart = offset()
  run.stage("ride right", {frames = 120, each = ride, done = function()
    return select(1, lift:getVelocity()) < 0
  end})
  t.near(px(lift), LIFT_RIGHT, 1.01, "the lift reached the right end")
  t.near(px(player) - px(lift), rideStart, 1e-3, "and carried the player there")
  run.stage("ride left", {frames = 20, each = ride})
  t.equal(select(1, lift:getVelocity()), -60, "the lift moves left")

  -- 8. Walk right at 150 on the lift moving left at 60: 2.5 a frame along it, 90 in the
  --    world.
  local before = offset()
  run.stage("walk on the moving lift", {move = 1, frames = 8, each = function(i)
    t.near(offset() - before, SPEED * dt * i, 1e-3, "walked along the lift, frame " .. i)
    t.near((player:getVelocity()), SPEED - 60, 1e-3, "its world velocity, frame " .. i)
  end})
  ride = riding(player, lift, "the lift")
  run.stage("ride to the right end again", {frames = 400, each = ride, done = function()
    return px(lift) >= LIFT_RIGHT - 1e-3
  end})

  -- 9. Off the lift onto the floor past the pit, and onto the vertical lift (at the
  --    bottom of its shaft, from x 802 to 862, its top flush with the floor).
  local up = level.upLift
  run.stage("walk onto the vertical lift", {move = 1, frames = 180, done = function()
    return onGround(player, up) and px(player) >= px(up)
  end})
  run.stage("settle on the vertical lift", {frames = 1})
  local rideUp = riding(player, up, "the vertical lift")
  -- Up 96 (to the shelf's top), a wait, down 96, up again.
  run.stage("ride up", {frames = 120, each = rideUp, done = function()
    return select(2, up:getVelocity()) == 0
  end})
  t.near(py(up), SHELF_TOP + 6, 1.01, "the lift at the top")
  run.stage("wait at the top, ride down", {frames = 200, each = rideUp, done = function()
    return select(2, up:getVelocity()) < 0
  end})
  t.near(py(up), FLOOR + 6, 1.01, "the lift came back down")
  run.stage("ride up again", {frames = 120, each = rideUp, done = function()
    return select(2, up:getVelocity()) == 0
  end})

  -- 10. Onto the shelf, and to the right wall (x 1008).
  run.stage("walk to the right wall", {move = 1, frames = 120, done = function()
    return player:getTouching().wallRight
  end})
  t.near(py(player), SHELF_TOP - HH, 0.05, "on the shelf")
  t.near(px(player), RIGHT_WALL - HW, 0.05, "against the wall")

  -- 11. Jump while pressed into the wall, too high to climb: it rises as in open air and
  --     falls back down beside it, never hanging (its velocity changes by g dt and nothing
  --     else every frame in the air), and lands on the shelf when a jump in open air would
  --     be back: after k steps it has risen (420 k - (g dt / 2) k (k + 1)) dt, 0 again
  --     for k + 1 = 2 x 420 / (g dt) = 63, so at the 62nd step.
  startY = py(player)
  highest = 0
  local lastVy
  local frames = run.stage("jump into the wall", {move = 1, jump = true, frames = 90,
    each = function(i)
      highest = math.max(highest, startY - py(player))
      local _, vy = player:getVelocity()
      if lastVy and not player:getGround() then
        t.near(vy - lastVy, g * dt, 1e-3, "gravity alone, frame " .. i)
      end
      lastVy = vy
    end, done = function(i) return i > 5 and onGround(player, onMap) end})
  t.near(highest, APEX, 0.01, "rose as in open air")
  t.equal(frames, 62, "landed after 62 steps")
  t.near(py(player), SHELF_TOP - HH, 0.05, "back on the shelf")
  t.near(px(player), RIGHT_WALL - HW, 0.05, "against the wall")
end)

-- The second player's code: a kinematic body moved by hand with world:move, bump.lua's
-- way, with its own gravity and jump. Its filter crosses the coin and slides on the rest.
local function newMover(level, body)
  local mover = {vy = 0, grounded = false, crossed = 0}
  local function filter(other)
    if other == level.coin then return "cross" end
    return "slide"
  end
  function mover.control(_, input)
    if input.jump and mover.grounded then mover.vy = -JUMP end
    mover.vy = mover.vy + g * dt
    local _, _, cols, len = level.world:move(body, input.move * SPEED * dt, mover.vy * dt, filter)
    mover.grounded = false
    for i = 1, len do
      local col = cols[i]
      if col.type == "cross" and col.other == level.coin then
        mover.crossed = mover.crossed + 1
      elseif col.normal.y < 0 then
        mover.grounded, mover.vy = true, 0
      elseif col.normal.y > 0 then
        mover.vy = 0
      end
    end
  end
  return mover
end

test("a kinematic player moved with world:move fetches the coin too", function()
  local level = newLevel()
  local body = level.world:newBody({type = "kinematic", x = 380, y = FLOOR - HH, hw = HW,
    hh = HH})
  local mover = newMover(level, body)
  local run = newRun(level, body, mover.control)
  run.stage("settle", {frames = 5})
  t.equal(mover.grounded, true, "on the floor")
  t.near(py(body), FLOOR - HH, 1e-4, "exactly on it")
  -- Right to under the platform at 150 (2.5 a frame): 27 frames from 380 to 447.5, 28 to 450.
  run.stage("walk under the one-way", {move = 1, frames = 60, each = function()
    t.equal(mover.grounded, true, "walking on the floor")
  end, done = function() return px(body) >= 448 end})
  t.equal(px(body), 450, "x")
  -- The same jump as the character's: up through the platform and the coin, down on the
  -- platform's top (192).
  local startY, highest = py(body), 0
  run.stage("jump through the one-way", {jump = true, frames = 90, each = function()
    highest = math.max(highest, startY - py(body))
  end, done = function(i) return i > 5 and mover.grounded end})
  t.near(highest, APEX, 0.01, "the same rise")
  t.equal(mover.crossed, 1, "crossed the coin once (move's collisions)")
  t.equal(run.coins, 1, "and the coin's sensor saw it (a sensor event)")
  t.near(py(body), 192 - HH, 1e-4, "on the one-way platform")
  t.equal(px(body), 450, "straight up and down")
end)

return t.run(tests)
