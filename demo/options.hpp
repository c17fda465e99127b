// The demo's command line.
#pragma once

#include <optional>
#include <string>

namespace jostle::demo {

struct Options {
    int sample = 1; ///< 1 to 9, as the keys
    /// Run this many frames, then exit (0: until the window is closed). Frames then count
    /// as 1/60 s each, whatever they really take, so that a run is the same every time.
    int frames = 0;
    /// Where to save the last frame before exiting, a PNG or a BMP by its name (empty:
    /// nowhere).
    std::string screenshot;
    /// Keyboard and mouse events by frame (--input): a file's name, or the script itself.
    std::string input;
    /// Print facts about the state at exit, one `name value` per line (--report).
    bool report = false;
    /// Only check that a window can be opened, then exit: 0 if it can.
    bool probe = false;
};

/// The options, or nothing if the program should exit with `exitCode` (--help, errors).
std::optional<Options> parseOptions(int argc, char** argv, int& exitCode);

} // namespace jostle::demo
