-- luarocks: the jostle module for the Lua luarocks runs for (Lua 5.1/LuaJIT, 5.4, ...).
-- From the root of a checkout:   luarocks make bindings/lua/jostle-0.1.0-1.rockspec
-- Its version is the library's (include/jostle/version.h); the test versions_agree checks.
-- The build needs cmake and a C++20 compiler: CMake builds the core and this one module
-- (JOSTLE_LUA_ROCK) and installs the module alone into the rock's tree.
rockspec_format = "3.0"
package = "jostle"
version = "0.1.0-1"
source = {
   -- The release's tarball; `luarocks make` builds the checkout it runs in instead.
   url = "jostle-0.1.0.tar.gz",
   dir = "jostle-0.1.0",
}
description = {
   summary = "2D collision detection and response for simple games",
   detailed = [[
Axis-aligned boxes, slopes and round shapes; static, kinematic and dynamic bodies;
stable stacks, characters, one-way platforms, sensors, events, queries and tile maps.
Same inputs, same results, bit for bit. docs/lua.md is the manual.]],
   license = "MIT",
   labels = { "physics", "collision", "games", "love2d" },
}
dependencies = {
   "lua >= 5.1",
}
build = {
   type = "cmake",
   variables = {
      CMAKE_BUILD_TYPE = "Release",
      CMAKE_INSTALL_PREFIX = "$(PREFIX)",
      JOSTLE_LUA_ROCK = "ON",
      JOSTLE_LUA_ROCK_INCDIR = "$(LUA_INCDIR)",
      JOSTLE_LUA_ROCK_LIBDIR = "$(LIBDIR)",
   },
}
