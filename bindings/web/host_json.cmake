# nlohmann-json for the web build: the host's header-only library (nlohmann-json3-dev),
# seen through a directory holding only its headers, since the host's /usr/include as a
# whole would shadow emscripten's C library. Defines nlohmann_json::nlohmann_json.
find_path(JOSTLE_HOST_JSON_DIR nlohmann/json.hpp PATHS /usr/include NO_CMAKE_FIND_ROOT_PATH
  NO_DEFAULT_PATH)
if(NOT JOSTLE_HOST_JSON_DIR)
  message(FATAL_ERROR "nlohmann/json.hpp not found: install nlohmann-json3-dev (scripts/setup.sh)")
endif()
set(json_include ${CMAKE_BINARY_DIR}/host-json)
file(MAKE_DIRECTORY ${json_include})
file(CREATE_LINK ${JOSTLE_HOST_JSON_DIR}/nlohmann ${json_include}/nlohmann SYMBOLIC)
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${json_include})
