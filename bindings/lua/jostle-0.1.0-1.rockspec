-- luarocks: the jostle module for the Lua luarocks runs for (Lua 5.1/LuaJIT, 5.4, ...).
-- From the root of a checkout:   luarocks make bindings/lua/jostle-0.1.0-1.rockspec
-- Its version is the library's (include/jostle/version.h); the test versions_agree checks.
-- The build needs cmake, a C++20 compiler and nlohmann-json's header (Debian's
-- nlohmann-json3-dev): CMake builds the core, the scene and level libraries and this one
-- module (JOSTLE_LUA_ROCK) and installs the module alone into the rock's tree. With
-- pugixml, zlib and zstd (libpugixml-dev zlib1g-dev libzstd-dev) levels are read in every
-- format Tiled saves; without them, JSON maps with plain or base64 data.
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
stable stacks, characters, one-way platforms, sensors, events, queries, tile maps
and levels drawn in Tiled or LDtk.
Same inputs, same results, bit for bit. docs/lua.md is the manual.]],
   license = "MIT",
   labels = { "physics", "collision", "games", "love2d" },
}
dependencies = {
   "lua >= 5.1",
}
external_dependencies = {
   NLOHMANN_JSON = { header = "nlohmann/json.hpp" },
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
