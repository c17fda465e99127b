// Open questions: findings of the fuzzers that wait for a design decision, not for a fix
// (tests/fuzz/open/README.md lists them with their reproducers). Until they are decided,
// the fuzzers leave out the inputs or the checks that find them, each at a place marked
// OPEN QUESTION, so that a run can find something new. The environment variable
// JOSTLE_FUZZ_OPEN names those to look at again, comma-separated, or "all".
#pragma once

#include "invariants.hpp"

#include <cstdlib>
#include <string>

namespace jostle::check {

/// True if JOSTLE_FUZZ_OPEN names `question` (or is "all").
inline bool checkOpen(const char* question) {
    // Appended piece by piece: g++ 12 warns (-Wrestrict) on "," + std::string(...).
    auto listed = [](const char* name) {
        std::string text(",");
        text += name;
        text += ',';
        return text;
    };
    static const std::string names = [&] {
        const char* value = std::getenv("JOSTLE_FUZZ_OPEN");
        return value ? listed(value) : std::string();
    }();
    return names.find(",all,") != std::string::npos ||
           names.find(listed(question)) != std::string::npos;
}

/// OPEN QUESTION squeezed-into-static: position correction can push a body deep into
/// static bodies for good. The body that presses on it touches the static body too, or is
/// pressed by one that does, so all are on the first support level, and position
/// correction between them is shared by inverse mass: the light body is pushed into the
/// static one as hard as the static one pushes it out (a plank under the end of a box 500
/// times heavier that landed on both: 1.66 deep, more than its half height; five small
/// boxes under a tall one, one of them wholly inside the floor). Moves of correction are
/// not swept, so a pile can also push its bottom box into a hole narrower than itself,
/// where the two sides hold it for good (a box 19 wide, 4.4 deep in the side of an
/// 11-wide hole in a tile floor). Which body should give way (the upper one, by position
/// along gravity, as the velocity solver decides support?) is a design decision. Until it
/// is taken, a squeezed body (check::squeezed) is not held to the slop.
inline bool excusedAsSqueezed(const World& world, BodyId body) {
    return !checkOpen("squeezed-into-static") && squeezed(world, body);
}

} // namespace jostle::check
