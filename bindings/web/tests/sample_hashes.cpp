// jostle-web-sample-hashes: every sample's check (sample_check.hpp) run natively, printed
// as the page's ?check writes it into its title: `name=hash` separated by spaces.
#include "sample_check.hpp"
#include "sample_list.hpp"

#include <cstdio>
#include <string>

int main() {
    std::string line;
    for (const auto& sample : jostle::demo::makeSamples())
        line += std::string(line.empty() ? "" : " ") + sample->name() + "=" +
                std::to_string(jostle::web::runSampleCheck(*sample, jostle::web::kCheckSteps));
    std::printf("%s\n", line.c_str());
    return 0;
}
