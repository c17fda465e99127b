// jostle-web-sample-hashes: every sample's check (sample_check.hpp) run natively, printed
// as the page's ?check writes it into its title: `name=hash` separated by spaces. With
// --time, the milliseconds each check took instead, as the page shows them beside its
// own (docs/web.md compares the two).
#include "sample_check.hpp"
#include "sample_list.hpp"

#include <chrono>
#include <cstdio>
#include <string>

int main(int argc, char** argv) {
    const bool time = argc > 1 && std::string(argv[1]) == "--time";
    std::string line;
    for (const auto& sample : jostle::demo::makeSamples()) {
        const auto start = std::chrono::steady_clock::now();
        const std::uint64_t hash = jostle::web::runSampleCheck(*sample, jostle::web::kCheckSteps);
        const std::chrono::duration<double, std::milli> took =
            std::chrono::steady_clock::now() - start;
        char ms[32];
        std::snprintf(ms, sizeof ms, "%.1f", took.count());
        line += std::string(line.empty() ? "" : " ") + sample->name() + "=" +
                (time ? std::string(ms) : std::to_string(hash));
    }
    std::printf("%s\n", line.c_str());
    return 0;
}
