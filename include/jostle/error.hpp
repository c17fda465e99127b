// jostle/error.hpp: how jostle reports misuse.
//
// Every public function checks its arguments. A bad argument (a stale, null or foreign
// BodyId, a NaN or infinite number, a number beyond the range jostle works in (magnitude
// above 1e9, or a size below 1e-9: math.hpp), a size <= 0, a value out of its range,
// dt <= 0, a world setting changed from a callback during step()) throws
// jostle::Error, whose what() names the argument and the rule it breaks, e.g.
// "createBody: BodyDef.hw: must be > 0". The world is left as it was before the call.
// (What a callback of yours throws during step() comes out of it once the step is whole:
// world.hpp, World::step.)
#pragma once

#include "jostle/visibility.h"
#include <stdexcept>

namespace jostle {
JOSTLE_EXPORT_BEGIN

class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

JOSTLE_EXPORT_END
} // namespace jostle
