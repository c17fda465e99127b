-- Run by CTest under `ulimit -v` (bindings/lua/CMakeLists.txt): a world of 64 workers whose
-- threads the system will not start raises a Lua error naming why; the interpreter used to
-- abort ("terminate called without an active exception").
local jostle = require("jostle")
local t = require("helper")

local tests = {}
tests[#tests + 1] = {"a world whose threads cannot start is a Lua error", function()
  t.raises({"jostle.newWorld", "workers = 64: the system would start only"},
    function() jostle.newWorld({workers = 64}) end)
  -- And the interpreter goes on: a world on the calling thread alone still steps.
  local world = jostle.newWorld({gravity = {0, 10}})
  local box = world:newBody({x = 0, y = 0, hw = 1, hh = 1})
  world:step(1 / 60)
  t.truthy(select(2, box:getVelocity()) > 0, "the step ran")
end}
return t.run(tests)
