# The Debian package (docs/packaging.md): `cpack -G DEB` in a build configured with
# CMAKE_INSTALL_PREFIX=/usr, which scripts/package.sh makes. One package, jostle: the static
# and the shared library, the headers, the CMake and pkg-config files, the jostle program,
# the Lua modules where Debian's Lua 5.4 and LuaJIT look, and the documents.

# The documents: the licence as Debian's copyright file, the changelog in Debian's format
# (from CHANGELOG.md's date for this version) and compressed as Debian wants, the manuals.
file(STRINGS ${PROJECT_SOURCE_DIR}/CHANGELOG.md jostle_release_line ENCODING UTF-8
     REGEX "^## ${PROJECT_VERSION} ")
string(REGEX MATCH "[0-9]+-[0-9]+-[0-9]+" jostle_release_date "${jostle_release_line}")
if(NOT jostle_release_date)
  message(FATAL_ERROR "CHANGELOG.md has no \"## ${PROJECT_VERSION} — <date>\" heading")
endif()
string(REPLACE "-" ";" jostle_ymd ${jostle_release_date})
list(GET jostle_ymd 0 jostle_year)
list(GET jostle_ymd 1 jostle_month)
list(GET jostle_ymd 2 jostle_day)
set(jostle_months Jan Feb Mar Apr May Jun Jul Aug Sep Oct Nov Dec)
math(EXPR jostle_month_index "${jostle_month} - 1")
list(GET jostle_months ${jostle_month_index} jostle_month_name)
set(JOSTLE_DEBIAN_DATE "${jostle_day} ${jostle_month_name} ${jostle_year} 00:00:00 +0000")
# Who answers for the package: set it when publishing one.
set(JOSTLE_MAINTAINER "jostle developers <jostle@example.org>"
    CACHE STRING "The Debian package's maintainer")

set(jostle_doc_dir ${CMAKE_INSTALL_DATAROOTDIR}/doc/jostle)
configure_file(${PROJECT_SOURCE_DIR}/cmake/debian/changelog.in
               ${PROJECT_BINARY_DIR}/debian/changelog @ONLY)
execute_process(COMMAND gzip -9nf ${PROJECT_BINARY_DIR}/debian/changelog)
install(FILES ${PROJECT_BINARY_DIR}/debian/changelog.gz ${PROJECT_SOURCE_DIR}/cmake/debian/copyright
              ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${jostle_doc_dir})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${jostle_doc_dir}/docs
        FILES_MATCHING PATTERN "*.md")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME jostle)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_CONTACT "${JOSTLE_MAINTAINER}")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${JOSTLE_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The synopsis is CPACK_PACKAGE_DESCRIPTION_SUMMARY; this is the text under it.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Axis-aligned boxes, slopes and round shapes; static,
kinematic and dynamic bodies; stable stacks, characters, one-way platforms,
sensors, events, queries and tile maps, with the same results bit for bit on
every machine. For C++20, C (jostle.h), Lua 5.4 and LuaJIT (LOVE), with the
jostle program for scene files and levels from Tiled and LDtk.")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The static level library links with these where a program uses it (jostle-level.pc,
# find_package(jostle COMPONENTS level)); the rest of the package needs none of them.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libpugixml-dev, zlib1g-dev, libzstd-dev")
# The shared library: what a package built against it depends on (shlibs), and ld.so's
# cache refreshed by a trigger, as Debian wants, not by maintainer scripts.
configure_file(${PROJECT_SOURCE_DIR}/cmake/debian/shlibs.in ${PROJECT_BINARY_DIR}/debian/shlibs
               @ONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/debian/triggers ${PROJECT_BINARY_DIR}/debian/triggers
               COPYONLY)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/debian/shlibs
                                       ${PROJECT_BINARY_DIR}/debian/triggers)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
