// Writing a Canvas to image files: a PNG (libpng) or the frames of an animated GIF
// (giflib). Failures come back as a message, not an exception: the command decides what
// they mean for its exit status.
#pragma once

#include "canvas.hpp"

#include <cstdio>
#include <span>
#include <string>

struct GifFileType; // giflib's, kept out of the header

namespace jostle::cli {

/// Writes `canvas`, its indices looked up in `palette`, to `file` as an RGB PNG. Returns
/// an empty string, or what went wrong. Leaves `file` open.
std::string writePng(std::FILE* file, const Canvas& canvas, std::span<const Rgb> palette);

/// An animated GIF that loops forever, written one frame at a time.
class GifWriter {
public:
    GifWriter() = default;
    GifWriter(const GifWriter&) = delete;
    GifWriter& operator=(const GifWriter&) = delete;
    ~GifWriter();

    /// Creates `path` for width × height frames of `palette` (at most 256 colours).
    /// Returns an empty string, or what went wrong.
    std::string open(const std::string& path, int width, int height, std::span<const Rgb> palette);
    /// Appends a frame shown for `delayCentiseconds`.
    std::string addFrame(const Canvas& canvas, int delayCentiseconds);
    /// Writes the trailer and closes the file.
    std::string close();

private:
    GifFileType* gif_ = nullptr;
};

} // namespace jostle::cli
