// Whether a world's own threads pay: its steps are timed with their work shared among the
// threads and on the calling thread alone, and the faster way is kept, the other tried
// again now and then. A step's results never depend on it (jostle/tasks.hpp), only its time.
#pragma once

#include <cstdint>

namespace jostle {

class SharingChoice {
public:
    /// Steps at the start that take turns, shared first, before the faster way is kept;
    /// a world's first step (its buffers growing) is not counted.
    static constexpr std::uint32_t kFirstTurns = 8;
    /// Once chosen, one step in this many goes the other way, to see whether it pays now
    /// (a world grows, the other core gets busy): at most a thirtieth of the steps lose.
    static constexpr std::uint32_t kRetryEvery = 32;
    /// How much a step's time moves its way's running mean (the rest: the mean so far).
    static constexpr float kWeight = 0.25f;

    /// Whether the next step shares its work.
    bool shareNext() const {
        if (steps_ <= kFirstTurns)
            return steps_ % 2 == 0;
        const bool faster = mean_[1] <= mean_[0];
        return steps_ % kRetryEvery == 0 ? !faster : faster;
    }

    /// A step took `ms`, shared or not.
    void record(bool shared, float ms) {
        if (steps_++ == 0)
            return;
        float& mean = mean_[shared ? 1 : 0];
        std::uint32_t& seen = seen_[shared ? 1 : 0];
        mean = seen++ == 0 ? ms : mean + kWeight * (ms - mean);
    }

private:
    std::uint32_t steps_ = 0;
    float mean_[2] = {0.0f, 0.0f}; ///< milliseconds a step, [0] alone, [1] shared
    std::uint32_t seen_[2] = {0, 0};
};

} // namespace jostle
