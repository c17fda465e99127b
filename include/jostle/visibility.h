// jostle/visibility.h: what the shared library exports (C or C++).
//
// The library is built with every symbol hidden; what the public headers declare between
// JOSTLE_EXPORT_BEGIN and JOSTLE_EXPORT_END is its interface, exported from libjostle.so.
// A game never needs these macros.
#ifndef JOSTLE_VISIBILITY_H
#define JOSTLE_VISIBILITY_H

#if defined(__GNUC__) || defined(__clang__)
#define JOSTLE_EXPORT_BEGIN _Pragma("GCC visibility push(default)")
#define JOSTLE_EXPORT_END _Pragma("GCC visibility pop")
#else
#define JOSTLE_EXPORT_BEGIN
#define JOSTLE_EXPORT_END
#endif

#endif // JOSTLE_VISIBILITY_H
