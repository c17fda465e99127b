-- Every row of every table of settings (src/body_properties.hpp, src/world_options.hpp),
-- as jostle-test-rows lists them: a Lua table with the field is read, and the value is given
-- back. World fields by the World's getters (getGravity, getWorkers, ...), options by
-- getClassicOptions and getPhysicalOptions (and their setters), bodies and tile maps by
-- getDef. A pointer is Lua's own: a body's userData is any Lua value; a map has none (a game
-- keys its own table by the map), so newTileMap refuses it. CMake gives the program's path
-- in JOSTLE_TEST_ROWS.
local jostle = require("jostle")
local t = require("helper")

local program = os.getenv("JOSTLE_TEST_ROWS")
assert(program, "JOSTLE_TEST_ROWS must name the jostle-test-rows program (CTest sets it)")
local pipe = assert(io.popen('"' .. program .. '" --lua'))
local rows = assert((loadstring or load)(pipe:read("*a")))()
pipe:close()

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

-- Values are equal, vectors number by number.
local function same(a, b)
  if type(a) == "table" and type(b) == "table" then
    return a[1] == b[1] and a[2] == b[2]
  end
  return a == b
end

local function expectSame(got, want, what)
  if not same(got, want) then
    error(string.format("%s: expected %s, got %s", what,
      type(want) == "table" and ("{" .. want[1] .. ", " .. want[2] .. "}") or tostring(want),
      type(got) == "table" and ("{" .. tostring(got[1]) .. ", " .. tostring(got[2]) .. "}")
        or tostring(got)), 2)
  end
end

-- A definition: what the row needs, and the row's field set to `value`.
local function definition(row, value)
  local def = {}
  for name, need in pairs(row.needs) do def[name] = need end
  def[row.name] = value
  return def
end

-- "workers" is getWorkers.
local function getterOf(name)
  return "get" .. name:sub(1, 1):upper() .. name:sub(2)
end

-- The options of a model ("classic"): read by newWorld and by their setter
-- (setClassicOptions), given back by their getter.
local function options(group)
  local getter = getterOf(group) .. "Options"
  local setter = "s" .. getter:sub(2)
  return function(row)
    local world = jostle.newWorld({[group] = definition(row, row.sample)})
    local other = jostle.newWorld()
    other[setter](other, definition(row, row.sample))
    expectSame(other[getter](other)[row.name], row.sample, setter .. ": " .. row.name)
    return world[getter](world)[row.name]
  end
end

-- What each table's rows are read into, and how the value comes back.
local readBack = {
  world = function(row)
    local world = jostle.newWorld(definition(row, row.sample))
    local got = {world[getterOf(row.name)](world)}
    return #got == 2 and got or got[1] -- gravity: x, y
  end,
  classic = options("classic"),
  physical = options("physical"),
  body = function(row, sample)
    return jostle.newWorld():newBody(definition(row, sample)):getDef()[row.name]
  end,
  tileMap = function(row, sample)
    return jostle.newWorld():newTileMap(definition(row, sample)):getDef()[row.name]
  end,
}
readBack.tasks = readBack.world -- Lua's newWorld has workers at its top level

test("every row of every table is read and given back", function()
  local seen = {}
  for _, row in ipairs(rows) do
    local what = row.table .. "." .. row.name
    local read = assert(readBack[row.table], "a table this test does not know: " .. row.table)
    if row.pointer and row.table == "tileMap" then
      t.raises({"World:newTileMap", 'unknown field "' .. row.name .. '"'}, read, row, {})
    elseif row.pointer then
      local value = {} -- any Lua value, given back as itself
      t.truthy(read(row, value) == value, what .. " is the value given")
    else
      expectSame(read(row, row.sample), row.sample, what)
    end
    seen[row.table] = (seen[row.table] or 0) + 1
  end
  for _, table in ipairs({"world", "tasks", "classic", "physical", "body", "tileMap"}) do
    t.truthy((seen[table] or 0) > 0, "rows of " .. table)
  end
end)

test("a value of the wrong type names its row", function()
  for _, row in ipairs(rows) do
    if not row.pointer then
      local wrong = type(row.sample) == "string" and 1 or "x"
      local words = {row.name .. ": expected"}
      if row.table == "classic" or row.table == "physical" then
        words = {row.table .. "." .. row.name .. ": expected"}
        t.raises(words, jostle.newWorld, {[row.table] = definition(row, wrong)})
      elseif row.table == "world" or row.table == "tasks" then
        t.raises(words, jostle.newWorld, definition(row, wrong))
      elseif row.table == "body" then
        local world = jostle.newWorld()
        t.raises(words, world.newBody, world, definition(row, wrong))
      else
        local world = jostle.newWorld()
        t.raises(words, world.newTileMap, world, definition(row, wrong))
      end
    end
  end
end)

return t.run(tests)
