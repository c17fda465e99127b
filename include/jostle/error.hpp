// jostle/error.hpp: how jostle reports misuse.
//
// Every public function checks its arguments. A bad argument (a stale or null BodyId,
// a NaN or infinite number, a size <= 0, a value out of its range, dt <= 0) throws
// jostle::Error, whose what() names the argument and the rule it breaks, e.g.
// "createBody: BodyDef.hw: must be > 0". The world is left as it was before the call.
#pragma once

#include <stdexcept>

namespace jostle {

class Error : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

} // namespace jostle
