// bench/timing.hpp: timing a piece of work, for the benchmark programs.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace jostle::bench {

/// The median of `runs` timings of `work`, in microseconds.
template <class Work> double medianMicroseconds(int runs, Work&& work) {
    using Clock = std::chrono::steady_clock;
    std::vector<double> times;
    for (int run = 0; run < runs; ++run) {
        const Clock::time_point start = Clock::now();
        work();
        times.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

} // namespace jostle::bench
