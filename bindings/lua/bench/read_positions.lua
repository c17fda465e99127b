-- What it costs to read every body's position from Lua, beside one step of the world: a
-- benchmark, not a test (scripts/bench-lua.sh builds the module and runs this; the
-- figures are in docs/benchmarks.md).
--
--   LUA_CPATH="build/lua/luajit/?.so" luajit bindings/lua/bench/read_positions.lua [bodies [repeats]]
--
-- The world: a gas of boxes, 8 x 8, in a grid 12 apart inside a closed box, with random
-- velocities, no gravity, no friction, bounce 1 and sleeping off, so that every body moves
-- at every step. After a warm-up, each way of reading runs `repeats` times (default 30)
-- and the median is printed, in milliseconds, for the step and for each way:
--   - getPosition per body: a Lua/C call per body, over the array of world:getBodies();
--   - getPositions(t): one call filling a table reused from one read to the next;
--   - getPositions(): the same into a new table each time (garbage for the collector);
--   - getPositionsBuffer: LuaJIT only, one call, then the floats read through the FFI.
-- Each way also adds up every coordinate it read, so that the reading is done in Lua as a
-- game drawing the bodies would, and the sums are compared: they must agree.
local jostle = require("jostle")

local count = tonumber(arg[1]) or 40000
local repeats = tonumber(arg[2]) or 30
local side = math.ceil(math.sqrt(count))
local spacing, half = 12, 4

local world = jostle.newWorld({gravity = {0, 0}, sleeping = false})
local extent = side * spacing
for _, wall in ipairs({{extent / 2, -10, extent / 2 + 20, 10}, {extent / 2, extent + 10, extent / 2 + 20, 10},
    {-10, extent / 2, 10, extent / 2}, {extent + 10, extent / 2, 10, extent / 2}}) do
  world:newBody({type = "static", x = wall[1], y = wall[2], hw = wall[3], hh = wall[4],
    friction = 0, bounce = 1})
end
-- A fixed sequence of velocities (a linear congruential generator): the same world every run.
local seed = 12345
local function random()
  seed = (seed * 1103515245 + 12345) % 2147483648
  return seed / 2147483648
end
local made = 0
for row = 0, side - 1 do
  for col = 0, side - 1 do
    if made < count then
      world:newBody({x = spacing * (col + 0.5), y = spacing * (row + 0.5), hw = half, hh = half,
        vx = 100 * random() - 50, vy = 100 * random() - 50, friction = 0, bounce = 1})
      made = made + 1
    end
  end
end
local dt = 1 / 60
for _ = 1, 30 do world:step(dt) end -- warm-up: the gas is mixing

local bodies = world:getBodies()
local total = #bodies

local function median(samples)
  table.sort(samples)
  local n = #samples
  return n % 2 == 1 and samples[(n + 1) / 2] or (samples[n / 2] + samples[n / 2 + 1]) / 2
end

-- Runs fn `repeats` times (after one run to warm it up); the median in milliseconds, and
-- what the last run returned.
local function measure(fn)
  local result = fn()
  local samples = {}
  for i = 1, repeats do
    local start = os.clock()
    result = fn()
    samples[i] = (os.clock() - start) * 1000
  end
  return median(samples), result
end

local rows = {}
local function row(name, fn)
  local ms, sum = measure(fn)
  rows[#rows + 1] = {name, ms, sum}
end

row("world:step(1/60)", function() world:step(dt) return 0 end)

row("getPosition per body", function()
  local sum = 0
  for i = 1, total do
    local x, y = bodies[i]:getPosition()
    sum = sum + x + y
  end
  return sum
end)

local reused = {}
row("getPositions(t), t reused", function()
  local t = world:getPositions(reused)
  local sum = 0
  for i = 1, 2 * total do sum = sum + t[i] end
  return sum
end)

row("getPositions(), a new table", function()
  local t = world:getPositions()
  local sum = 0
  for i = 1, 2 * total do sum = sum + t[i] end
  return sum
end)

if jit then
  local ffi = require("ffi")
  row("getPositionsBuffer, FFI", function()
    local pointer, n = world:getPositionsBuffer()
    local p = ffi.cast("float*", pointer)
    local sum = 0
    for i = 0, 2 * n - 1 do sum = sum + p[i] end
    return sum
  end)
end

print(string.format("%s%s, %d bodies (%d moving), median of %d runs", _VERSION,
  jit and (" / " .. jit.version) or "", total, made, repeats))
print(string.format("%-30s %10s %12s", "", "ms", "x the step"))
local step = rows[1][2]
local reference
for i, r in ipairs(rows) do
  print(string.format("%-30s %10.3f %12.3f", r[1], r[2], r[2] / step))
  -- Every way read the same positions (the world does not move between them).
  if i > 1 then
    reference = reference or r[3]
    assert(r[3] == reference, r[1] .. " read other positions than getPosition")
  end
end
