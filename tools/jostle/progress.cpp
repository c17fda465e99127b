// The progress line: see progress.hpp.
#include "progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <utility>

namespace jostle::cli {

namespace {

/// The least time between two drawings: a few a second is lively enough to read, and
/// costs nothing next to the steps.
constexpr std::chrono::milliseconds kInterval{250};

} // namespace

Progress::Progress(std::string label, std::int64_t total, bool stdoutBusy)
    : label_(std::move(label)), total_(total),
      shown_(total > 0 && ::isatty(STDERR_FILENO) == 1 &&
             !(stdoutBusy && ::isatty(STDOUT_FILENO) == 1)) {
    if (shown_)
        redraw(0, true);
}

void Progress::redraw(std::int64_t done, bool now) {
    const auto time = std::chrono::steady_clock::now();
    if (!now && time - last_ < kInterval)
        return;
    last_ = time;
    const int percent =
        static_cast<int>(100.0 * static_cast<double>(done) / static_cast<double>(total_));
    // Never shorter than the line before it: the numbers only grow.
    std::string line = "\r";
    line.append(label_).append(": step ").append(std::to_string(done));
    line.append(" of ").append(std::to_string(total_));
    line.append(" (").append(std::to_string(percent)).append("%)");
    drawn_ = line.size() - 1;
    std::fputs(line.c_str(), stderr);
}

void Progress::erase() {
    if (!shown_)
        return;
    shown_ = false;
    std::string blank = "\r";
    blank.append(drawn_, ' ').append("\r");
    std::fputs(blank.c_str(), stderr);
}

} // namespace jostle::cli
