// jostle-demo: jostle's samples in an SDL2 window (docs/demo.md).
#include "app.hpp"
#include "options.hpp"

#include "jostle/error.hpp"

#include <SDL.h>

#include <cstdio>
#include <exception>

int main(int argc, char** argv) {
    int exitCode = 0;
    const auto options = jostle::demo::parseOptions(argc, argv, exitCode);
    if (!options)
        return exitCode;
    try {
        return options->probe ? jostle::demo::probeDisplay() : jostle::demo::runApp(*options);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "jostle-demo: %s\n", error.what());
        return 1;
    }
}
