// jostle-bench-dispatch: what handing a loop's blocks to the workers costs (docs/threads.md):
// a loop of four one-item blocks that do next to nothing, run after a stretch of serial work
// of each length, on 1 and 2 workers. While the other thread still spins, a hand-out costs
// its synchronisation; once it has gone to sleep, waking it too. Medians of --runs runs.
//   jostle-bench-dispatch [--runs N] [--calls N]
#include "tasks.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace {

using namespace jostle;
using Clock = std::chrono::steady_clock;

double microsecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::micro>(Clock::now() - start).count();
}

/// Serial work of about `microseconds`, as a step's serial stages are between two loops.
void serialWork(double microseconds) {
    const auto start = Clock::now();
    while (microsecondsSince(start) < microseconds) {
    }
}

} // namespace

int main(int argc, char** argv) {
    int runs = 3;
    int calls = 2000;
    CLI::App app{"jostle-bench-dispatch: the cost of handing a loop to the workers",
                 "jostle-bench-dispatch"};
    app.add_option("--runs", runs, "Runs of each measure (the median is printed)")
        ->check(CLI::Range(1, 1000));
    app.add_option("--calls", calls, "Loops handed out a run")->check(CLI::Range(1, 10000000));
    CLI11_PARSE(app, argc, argv);

    const double gaps[] = {0, 20, 100, 300, 1000};
    std::printf("| serial work between two loops, µs |");
    for (double gap : gaps)
        std::printf(" %.0f |", gap);
    std::printf("\n|---|");
    for (std::size_t k = 0; k < std::size(gaps); ++k)
        std::printf("---:|");
    std::printf("\n");
    for (int workers : {1, 2}) {
        TaskRunner runner(TaskSystem{.workers = workers});
        std::vector<int> touched(4);
        std::printf("| a loop on %d worker%s, µs |", workers, workers == 1 ? "" : "s");
        for (double gap : gaps) {
            std::vector<double> medians;
            for (int run = 0; run < runs; ++run) {
                double total = 0.0;
                for (int call = 0; call < calls; ++call) {
                    serialWork(gap);
                    const auto start = Clock::now();
                    runner.forEachBlock(4, 1, [&](Block block) { ++touched[block.index]; });
                    total += microsecondsSince(start);
                }
                medians.push_back(total / calls);
            }
            std::sort(medians.begin(), medians.end());
            std::printf(" %.2f |", medians[medians.size() / 2]);
        }
        std::printf("\n");
    }
}
