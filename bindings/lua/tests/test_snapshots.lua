-- Snapshots: world:snapshot() as a string, world:restore(s), world:stateHash(): a rolled
-- back world steps on as it did the first time, bit for bit.
local jostle = require("jostle")
local t = require("helper")

local tests = {}
local function test(name, fn) tests[#tests + 1] = {name, fn} end

local function pile()
  local world = jostle.newWorld({gravity = {0, 600}})
  world:newBody({type = "static", x = 0, y = 10, hw = 200, hh = 10})
  local boxes = {}
  for i = 1, 6 do
    boxes[i] = world:newBody({x = i * 11 - 35, y = -10 - i * 12, hw = 5, hh = 5, bounce = 0.4})
  end
  t.steps(world, 20)
  return world, boxes
end

test("a restored world steps on as the world it was taken from", function()
  local world, boxes = pile()
  local saved = world:snapshot()
  t.equal(type(saved), "string", "the snapshot is a string")
  t.equal(saved:sub(1, 8), "JSTLSNAP", "of bytes that say what they are")
  local hash = world:stateHash()
  t.equal(#hash, 16, "the hash is 16 hexadecimal digits")
  t.steps(world, 60)
  local x, y = boxes[6]:getPosition()
  local later = world:stateHash()
  t.truthy(later ~= hash, "a second later the world differs")

  world:restore(saved)
  t.equal(world:stateHash(), hash, "restored: the snapshot's state")
  t.steps(world, 60)
  local x2, y2 = boxes[6]:getPosition()
  t.equal(x2, x, "the same x")
  t.equal(y2, y, "the same y")
  t.equal(world:stateHash(), later, "the same state")
end)

test("bodies made since the snapshot are gone; the ones destroyed are back", function()
  local world, boxes = pile()
  local saved = world:snapshot()
  boxes[1]:destroy()
  local extra = world:newBody({x = 100, y = -50, hw = 3, hh = 3})
  world:restore(saved)
  t.truthy(not boxes[1]:isDestroyed(), "destroyed since: back")
  t.truthy(extra:isDestroyed(), "made since: gone")
  t.equal(world:getBodyCount(), 7, "the bodies of the snapshot")
end)

test("what is not a snapshot is refused, and the world stays as it was", function()
  local world = pile()
  local saved = world:snapshot()
  local hash = world:stateHash()
  t.raises({"World:restore", "not a jostle snapshot"}, world.restore, world, "hello")
  t.raises({"World:restore", "truncated snapshot"}, world.restore, world, saved:sub(1, -2))
  t.raises({"World:restore", "expected a string"}, world.restore, world, 42)
  t.equal(world:stateHash(), hash, "unchanged")
end)

test("a world restored from another's snapshot adopts its bodies", function()
  local world, boxes = pile()
  local saved = world:snapshot()
  local loaded = jostle.newWorld()
  loaded:restore(saved)
  local adopted = loaded:adopt(boxes[3])
  t.truthy(adopted ~= nil and adopted:getWorld() == loaded, "this world's body")
  local x, y = adopted:getPosition()
  local x0, y0 = boxes[3]:getPosition()
  t.equal(x, x0, "the same x")
  t.equal(y, y0, "the same y")
  t.equal(loaded:adopt(boxes[3]), adopted, "one userdata a body")
  boxes[3]:destroy()
  local reused = world:newBody({x = 0, y = 0, hw = 1, hh = 1}) -- its slot, a newer generation
  t.equal(loaded:adopt(reused), nil, "no body of that generation there")
  t.raises({"World:adopt", "other: expected a Body or a TileMap, got number"}, loaded.adopt, loaded, 5)
end)

return t.run(tests)
