-- A scripted player walks a level of hills, written as a newcomer would from docs/lua.md:
-- ramp tiles in a tile map's rows, a character that keeps to the ground over the crests, a ball rolling (sliding) down a ramp into a coin's sensor, and
-- a ramp dug out with setTile at run time. Each stage checks where the player is against
-- the level's geometry.
local jostle = require("jostle")
local t = require("helper")

local g, dt, TILE = 800, 1 / 60, 16
local SPEED = 120
local HW, HH = 6, 8

-- y grows downward; the floor's top is y = 96 (row 6). A hill: a 45° ramp up from
-- x = 96 to 128, a flat top (y = 64) to x = 176, a 2:1 ramp down from x = 176 to 208
-- (tiles L and l), and a 45° valley wall ('\') down to the floor at x = 224 ... as drawn:
local ROWS = {
  "#..............................#", -- 0
  "#..............................#", -- 1
  "#..............................#", -- 2
  "#..............................#", -- 3
  "#....../###Ll..................#", -- 4
  "#...../#######Ll...............#", -- 5
  "################################", -- 6
}
local FLOOR = 96

-- The surface under x, from the rows: flat floor, 45° up from (80, 96) to (112, 64)...
-- Tiles: '/' at (6, 5) rises from (96, 96) to (112, 80), '/' at (7, 4) from (112, 80) to
-- (128, 64); '#' top at y = 64 from x = 128 to 176; 'Ll' at (11, 4)-(12, 4) falls from
-- (176, 64) to (208, 80); 'Ll' at (14, 5)-(15, 5) falls from (224, 80) to (256, 96), with
-- the '#' of row 5 (x 208 to 224, top y = 80) between them.
local function surface(x)
  if x < 96 then return FLOOR end
  if x < 128 then return FLOOR - (x - 96) end
  if x <= 176 then return 64 end
  if x < 208 then return 64 + (x - 176) / 2 end
  if x <= 224 then return 80 end
  if x < 256 then return 80 + (x - 224) / 2 end
  return FLOOR
end

-- A box on a slope stands on the corner nearest the top: going up to the right, its
-- right corner; going down, its left corner. So its centre is HH above the higher of the
-- surface under its two sides.
local function standingY(x)
  return math.min(surface(x - HW), surface(x + HW)) - HH
end

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

test("a character with snapDown walks over the hills on the ground at every step", function()
  local world = jostle.newWorld({gravity = {0, g}})
  world:newTileMap({tile = TILE, rows = ROWS})
  local player = world:newBody({x = 40, y = FLOOR - HH, hw = HW, hh = HH, character = true,
                                snapDown = 4})
  player:setWalkSpeed(SPEED)
  local steps = 0
  while select(1, player:getPosition()) < 280 and steps < 400 do
    world:step(dt)
    steps = steps + 1
    local x, y = player:getPosition()
    local vx = player:getVelocity()
    t.truthy(player:getTouching().floor, ("on the ground at step %d (x %.2f)"):format(steps, x))
    t.near(vx, SPEED, 0.01 * SPEED, ("walking at its speed at step %d"):format(steps))
    t.near(y, standingY(x), 0.05, ("on the surface at x %.2f"):format(x))
  end
  -- (280 - 40) / 120 s = 2 s = 120 steps: no step lost at any junction.
  t.equal(steps, 120, "over the hills in 2 s")
end)

test("without snapDown a character stays on the ground too; a crate flies off the crest", function()
  -- A character snaps by at least what a step at its walk speed drops on the steepest
  -- floor it stands on: 120 / 60 tan 60° = 3.5, more than the 2 of the 45° ramp.
  local world = jostle.newWorld({gravity = {0, g}})
  world:newTileMap({tile = TILE, rows = ROWS})
  local player = world:newBody({x = 40, y = FLOOR - HH, hw = HW, hh = HH, character = true})
  player:setWalkSpeed(SPEED)
  for step = 1, 120 do
    world:step(dt)
    t.truthy(player:getTouching().floor, ("on the ground at step %d"):format(step))
  end
  -- A frictionless crate sent at 400 keeps 400 cos 45° = 283 along the ramp, tops it (32
  -- high) at sqrt(283² - 2 g 32) = 170 and leaves the crest rising at 120, to 120² / 2g = 9.
  local crate = world:newBody({x = 40, y = FLOOR - HH, hw = HW, hh = HH, vx = 400, friction = 0})
  local airborne, top = 0, math.huge
  for _ = 1, 100 do
    world:step(dt)
    if not crate:getTouching().floor then airborne = airborne + 1 end
    top = math.min(top, select(2, crate:getPosition()))
  end
  t.truthy(airborne > 5, "off the ground for a while")
  t.truthy(64 - HH - top > 3, ("it rose %.2f above the top"):format(64 - HH - top))
end)

test("a ball slides down a ramp into a coin, and a ramp dug out lets a crate fall", function()
  local world = jostle.newWorld({gravity = {0, g}})
  local map = world:newTileMap({tile = TILE, rows = ROWS})
  -- The ball on the right side of the hill's top, the coin at the valley's bottom.
  local ball = world:newBody({x = 172, y = 64 - 5, hw = 5, hh = 5, radius = 5, friction = 0})
  local coin = world:newBody({type = "static", x = 216, y = 72, hw = 4, hh = 4, sensor = true})
  ball:setVelocity(30, 0)
  local got = false
  for _ = 1, 120 do
    world:step(dt)
    for _, e in ipairs(world:getSensorBegins()) do
      if e.sensor == coin and e.visitor == ball then got = true end
    end
  end
  t.truthy(got, "the ball reached the coin")
  t.equal(map:tileOf(7, 4), "/", "a ramp tile reads back")
  -- A crate resting on the hill's flat top (y = 64) over tile (9, 4), x 144 to 160; dig
  -- that tile out and the crate falls into the hole onto row 5's top, y = 80.
  local crate = world:newBody({x = 152, y = 0, hw = 4, hh = 4})
  for _ = 1, 60 do world:step(dt) end
  t.near(select(2, crate:getPosition()), 64 - 4, 0.05, "the crate on the flat top")
  map:setTile(9, 4, ".")
  for _ = 1, 60 do world:step(dt) end
  t.near(select(2, crate:getPosition()), 80 - 4, 0.05, "in the hole dug under it")
end)

return t.run(tests)
