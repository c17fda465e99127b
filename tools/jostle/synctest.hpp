// `jostle synctest`: rolls a scene back at every step and steps it again, as a rollback
// game does, checking that the world comes out the same, bit for bit (docs/rollback.md).
#pragma once

#include <cstdint>
#include <string>

namespace jostle::cli {

struct SyncTestOptions {
    std::string scene;
    std::int64_t steps = 300;
    std::int64_t rollback = 8; ///< K: how many steps each rollback goes back
    std::int64_t workers = 1;
    std::string solver; ///< --solver: empty for the scene's own
    /// For testing the test: in the re-simulation of this step (0: never), one body's
    /// velocity is nudged by a bit, which the test must then report.
    std::int64_t nudge = 0;
};

/// Steps the scene; after each step t >= K restores the snapshot of step t - K, steps K
/// steps again and compares the state hash (and, if it differs, the bodies) with the
/// snapshot of step t. Prints the verdict; returns 0, or 1 naming the first step, body and
/// field that differ.
int syncTest(const SyncTestOptions& options);

} // namespace jostle::cli
