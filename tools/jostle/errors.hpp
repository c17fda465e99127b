// How every command of the jostle program reports a problem: one line on stderr and an
// exit status that tells bad input (2) from a failure to write or a surprise (1).
#pragma once

#include <cstdio>
#include <string>
#include <system_error>

namespace jostle::cli {

constexpr int kBadInput = 2;
constexpr int kFailure = 1;

inline void printError(const std::string& message) {
    std::fprintf(stderr, "jostle: error: %s\n", message.c_str());
}

/// A warning: the run goes on, and its output is whole, but something in it is off.
inline void printWarning(const std::string& message) {
    std::fprintf(stderr, "jostle: warning: %s\n", message.c_str());
}

/// The words for an errno value, e.g. "No such file or directory".
inline std::string systemMessage(int error) {
    return std::error_code(error, std::generic_category()).message();
}

} // namespace jostle::cli
