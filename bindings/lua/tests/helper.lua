-- Shared by the Lua tests: a tiny runner and assertions that say what went wrong.
-- Each test file ends with `return helper.run(tests)`, where tests is a list of
-- {name, function}. A failed assertion raises an error; the runner reports it and the
-- script exits with status 1, which is what CTest looks at.
local helper = {}

local function describe(value)
  if type(value) == "string" then
    return string.format("%q", value)
  end
  return tostring(value)
end

function helper.equal(actual, expected, what)
  if actual ~= expected then
    error(string.format("%s: expected %s, got %s", what or "value", describe(expected),
      describe(actual)), 2)
  end
end

function helper.near(actual, expected, tolerance, what)
  if type(actual) ~= "number" or math.abs(actual - expected) > tolerance then
    error(string.format("%s: expected %.9g within %.3g, got %s", what or "value", expected,
      tolerance, describe(actual)), 2)
  end
end

function helper.truthy(value, what)
  if not value then
    error((what or "condition") .. ": expected true, got " .. describe(value), 2)
  end
end

-- Calls fn(...) and checks that it raises an error whose message contains each of the
-- words (plain text, not patterns). Returns the message.
function helper.raises(words, fn, ...)
  local ok, message = pcall(fn, ...)
  if ok then
    error("expected an error containing " .. describe(table.concat(words, " ... "))
      .. ", but the call succeeded", 2)
  end
  message = tostring(message)
  for _, word in ipairs(words) do
    if not message:find(word, 1, true) then
      error(string.format("expected an error containing %s, got %s", describe(word),
        describe(message)), 2)
    end
  end
  return message
end

function helper.steps(world, n, dt)
  for _ = 1, n do
    world:step(dt or 1 / 60)
  end
end

function helper.run(tests)
  local failed = 0
  for _, test in ipairs(tests) do
    local name, fn = test[1], test[2]
    local ok, message = xpcall(fn, debug.traceback)
    if ok then
      print("ok      " .. name)
    else
      failed = failed + 1
      print("FAILED  " .. name .. "\n" .. tostring(message))
    end
  end
  print(string.format("%s: %d tests, %d failed", _VERSION .. (jit and (" / " .. jit.version) or ""),
    #tests, failed))
  -- true: close the state, so that every world is collected (its finalizer runs) first.
  os.exit(failed == 0 and 0 or 1, true)
end

return helper
