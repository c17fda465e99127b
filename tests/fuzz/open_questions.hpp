// Open questions: findings of the fuzzers that wait for a design decision, not for a fix
// (tests/fuzz/open/README.md lists them with their reproducers). Until they are decided,
// the fuzzers leave out the inputs or the checks that find them, each at a place marked
// OPEN QUESTION, so that a run can find something new. The environment variable
// JOSTLE_FUZZ_OPEN names those to look at again, comma-separated, or "all".
#pragma once

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

} // namespace jostle::check
