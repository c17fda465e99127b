// Parsing the command line: see options.hpp.
#include "options.hpp"

#include "screenshot.hpp"

#include <CLI/CLI.hpp>

namespace jostle::demo {

std::optional<Options> parseOptions(int argc, char** argv, int& exitCode) {
    Options options;
    CLI::App app{"jostle-demo: jostle's samples in a window (docs/demo.md)", "jostle-demo"};
    app.add_option("--sample", options.sample, "the sample to start with, 1 to 9")
        ->check(CLI::Range(1, 9));
    app.add_option("--frames", options.frames,
                   "run this many frames (each counted as 1/60 s) and exit")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--screenshot", options.screenshot,
                   "with --frames, save the last frame to this file before exiting: a PNG "
                   "if its name ends in .png, else a BMP")
        ->check([](const std::string& path) {
            return isPngName(path) && !canWritePng()
                       ? std::string("this jostle-demo was built without libpng: save a .bmp")
                       : std::string();
        });
    app.add_option("--input", options.input,
                   "play keyboard and mouse events by frame: a file, or the script itself");
    app.add_flag("--report", options.report,
                 "at exit, print the sample, body count, flags and player, one per line");
    app.add_flag("--probe", options.probe, "exit 0 if a window can be opened, 1 if not");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        exitCode = app.exit(error);
        return std::nullopt;
    }
    return options;
}

} // namespace jostle::demo
