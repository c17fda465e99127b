// jostle/version.h: the version of these headers (C or C++). The one place the version
// is written: CMake, the packages, the Lua module and the JavaScript module read it from
// here. jostle_version() (jostle.h) gives the version of the library a program runs with.
//
// The version is major.minor.patch. Before 1.0, a new minor version may change the API
// and the shared library's ABI; a patch keeps both. CHANGELOG.md says what changed.
#ifndef JOSTLE_VERSION_H
#define JOSTLE_VERSION_H

#define JOSTLE_VERSION_MAJOR 0
#define JOSTLE_VERSION_MINOR 1
#define JOSTLE_VERSION_PATCH 0
#define JOSTLE_VERSION_STRING "0.1.0"

#endif // JOSTLE_VERSION_H
