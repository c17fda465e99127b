// How a cost grows with size, measured so that a busy machine cannot fail a test: the
// same work at two sizes in one process, each the best of a few runs, compared as a
// ratio. Linear work at ten times the size takes about ten times as long whatever else
// the machine does; quadratic work takes a hundred.
#pragma once

#include <algorithm>
#include <chrono>
#include <functional>

namespace jostle::test_support {

/// The shortest of `runs` runs of `work`, in seconds.
inline double bestTimeOf(const std::function<void()>& work, int runs = 3) {
    double best = 1e300;
    for (int run = 0; run < runs; ++run) {
        const auto start = std::chrono::steady_clock::now();
        work();
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        best = std::min(best, took.count());
    }
    return best;
}

/// The most a test lets ten times the work take, as a multiple of the time of the work:
/// linear work takes about ten times as long, and up to four times that where the larger
/// outgrows the caches the smaller fits (35-38 on an AMD EPYC with 512 KB of L2 a core) or
/// the other core is busy with memory; quadratic work takes a hundred times and more.
inline constexpr double kTenTimesTheWorkAtMost = 60.0;

/// How many times longer `large` takes than `small`.
inline double growthOf(const std::function<void()>& small, const std::function<void()>& large) {
    const double smallTime = bestTimeOf(small);
    return bestTimeOf(large) / std::max(smallTime, 1e-9);
}

} // namespace jostle::test_support
