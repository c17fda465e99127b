-- jostle.loadTiled and jostle.loadLdtk (docs/levels.md): the example level of
-- examples/levels/ from Tiled's and LDtk's files, its world made, its objects by name with
-- their bodies and properties. The level has a spawn point at (40, 200), a kinematic lift
-- whose property top is 104, two crates that fall onto the floor (its top at y 224) and
-- rest stacked at 216 and 200, and three coins.
local helper = require("helper")
local jostle = require("jostle")

local levels = "../../../examples/levels/"

local function named(objects, name)
  local found = {}
  for _, o in ipairs(objects) do
    if o.name == name then found[#found + 1] = o end
  end
  return found
end

local function checkExample(world, objects)
  helper.equal(#objects, 7, "objects: spawn, lift, 2 crates, 3 coins")
  local spawn = named(objects, "spawn")[1]
  helper.equal(spawn.x, 40, "spawn.x")
  helper.equal(spawn.y, 200, "spawn.y")
  helper.equal(spawn.body, nil, "the spawn point has no body")
  local lift = named(objects, "lift")[1]
  helper.equal(lift.body:getType(), "kinematic", "the lift's body")
  helper.equal(lift.properties.top, 104, "the lift's property top")
  helper.equal(#named(objects, "coin"), 3, "three coins")
  for _ = 1, 120 do world:step(1 / 60) end
  local ys = {}
  for _, crate in ipairs(named(objects, "crate")) do
    local _, y = crate.body:getPosition()
    ys[#ys + 1] = y
  end
  table.sort(ys)
  helper.near(ys[1], 200, 0.05, "the upper crate")
  helper.near(ys[2], 216, 0.05, "the lower crate")
end

local tests = {
  {"a Tiled map", function()
    checkExample(jostle.loadTiled(levels .. "level.tmx"))
  end},
  {"its JSON export", function()
    checkExample(jostle.loadTiled(levels .. "level.tmj"))
  end},
  {"the same level in LDtk", function()
    checkExample(jostle.loadLdtk(levels .. "level.ldtk", "Level_0"))
  end},
  {"refusals name the file", function()
    helper.raises({"jostle.loadTiled: nowhere.tmj: cannot read the file"},
      function() jostle.loadTiled("nowhere.tmj") end)
    helper.raises({"level.ldtk: no level \"Level_9\""},
      function() jostle.loadLdtk(levels .. "level.ldtk", "Level_9") end)
    helper.raises({"jostle.loadLdtk: kinds: expected"},
      function() jostle.loadLdtk(levels .. "level.ldtk", "Level_0", {[1] = 5}) end)
  end},
}

return helper.run(tests)
