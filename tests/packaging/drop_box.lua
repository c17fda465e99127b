-- Drops a box on a floor through the jostle module that require finds; the first argument
-- is the version the module must report. Exits non-zero (an error) otherwise.
local jostle = require("jostle")
local want = assert(arg[1], "usage: drop_box.lua VERSION")
assert(jostle.version == want, "jostle.version is " .. tostring(jostle.version) .. ", not " .. want)
local world = jostle.newWorld({gravity = {0, 800}})
world:newBody({type = "static", x = 0, y = 100, hw = 100, hh = 10})
local box = world:newBody({x = 0, y = 0, hw = 10, hh = 10})
for _ = 1, 120 do world:step(1 / 60) end
-- The floor's top is at y = 90, so the resting box's centre is at 80.
local _, y = box:getPosition()
assert(y > 79 and y < 81, "the box rests at y = " .. y .. ", not 80")
print(string.format("%s: jostle %s, box at y = %g", _VERSION, jostle.version, y))
