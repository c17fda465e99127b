// Whether a world's own threads pay: its steps are timed with their work shared among the
// threads and on the calling thread alone, and the faster way is kept, the other tried
// again now and then. A step's results never depend on it (jostle/tasks.hpp), only its time.
#pragma once

#include <cstdint>

namespace jostle {

class SharingChoice {
public:
    /// Steps at the start that take turns two by two, shared first, before the faster way
    /// is kept.
    static constexpr std::uint32_t kFirstTurns = 8;
    /// Once chosen, two steps in this many go the other way, to see whether it pays now (a
    /// world grows, the other core gets busy): at most a thirty-second of the steps lose.
    static constexpr std::uint32_t kRetryEvery = 64;
    static constexpr std::uint32_t kRetrySteps = 2;
    /// How much a step's time moves its way's running mean (the rest: the mean so far).
    static constexpr float kWeight = 0.25f;

    /// Whether the next step shares its work.
    bool shareNext() const {
        if (steps_ < kFirstTurns)
            return steps_ / 2 % 2 == 0;
        const bool faster = mean_[1] <= mean_[0];
        return steps_ % kRetryEvery < kRetrySteps ? !faster : faster;
    }

    /// A step took `ms`, shared or not. Not counted: a world's first step (its buffers
    /// grow), and a step that follows one of the other way, which finds the step's data in
    /// the other way's caches (in the other core's, or all in this one's).
    void record(bool shared, float ms) {
        const bool counted = steps_ != 0 && shared == lastShared_;
        ++steps_;
        lastShared_ = shared;
        if (!counted)
            return;
        float& mean = mean_[shared ? 1 : 0];
        std::uint32_t& seen = seen_[shared ? 1 : 0];
        mean = seen++ == 0 ? ms : mean + kWeight * (ms - mean);
    }

private:
    std::uint32_t steps_ = 0;
    bool lastShared_ = false;
    float mean_[2] = {0.0f, 0.0f}; ///< milliseconds a step, [0] alone, [1] shared
    std::uint32_t seen_[2] = {0, 0};
};

} // namespace jostle
