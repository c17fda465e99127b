// jostle_version: the library's version, from jostle/version.h as it was compiled.
#include "jostle/jostle.h"

extern "C" const char* jostle_version(void) {
    return JOSTLE_VERSION_STRING;
}
