// Writing a Canvas to image files: a PNG (libpng) or the frames of an animated GIF
// (giflib). Failures come back as a message, not an exception: the command decides what
// they mean for its exit status.
#pragma once

#include "canvas.hpp"

#include <cstdint>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

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
    /// Returns an empty string, or what went wrong (the errno's words for a file or a
    /// write that failed, as below).
    std::string open(const std::string& path, int width, int height, std::span<const Rgb> palette);
    /// Appends a frame shown for `delayCentiseconds`: the canvas as it is, written as the
    /// rectangle of pixels that differ from the frame before.
    std::string addFrame(const Canvas& canvas, int delayCentiseconds);
    /// Writes the trailer and closes the file; the reason of the first write that failed,
    /// if one did.
    std::string close();

private:
    /// giflib's output function: writes to file_, keeping the errno of the first failure.
    static int write(GifFileType* gif, const unsigned char* bytes, int length);
    /// What a giflib call that failed with `gifError` means: the reason of a failed write
    /// if there was one (giflib's own words are "Write failed (disk full?)").
    std::string failure(int gifError) const;

    std::FILE* file_ = nullptr;
    GifFileType* gif_ = nullptr;
    int error_ = 0;                  ///< the errno of the first write that failed, or 0
    std::vector<std::uint8_t> last_; ///< the last frame's pixels, row after row; none yet
};

} // namespace jostle::cli
