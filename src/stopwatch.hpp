// A wall clock for the step profile (World::profile): laps in milliseconds.
#pragma once

#include <chrono>

namespace jostle {

class Stopwatch {
public:
    /// Milliseconds since the stopwatch was made or last lapped; the next lap starts now.
    float lap() {
        const Clock::time_point now = Clock::now();
        const float ms = std::chrono::duration<float, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_ = Clock::now();
};

} // namespace jostle
