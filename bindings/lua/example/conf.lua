-- LÖVE settings for the jostle example. The example needs graphics, a window, the
-- keyboard and the mouse; love.physics (Box2D) is not used: jostle takes its place.
function love.conf(t)
  t.identity = "jostle-example"
  t.version = "11.0"
  t.window.title = "jostle: collision response"
  t.window.width = 800
  t.window.height = 600
  t.window.vsync = 1
  t.modules.physics = false
  -- No sound: the example makes none, and a machine without audio (a test under Xvfb)
  -- then needs no audio driver.
  t.modules.audio = false
  t.modules.sound = false
  t.modules.joystick = false
end
