// Animated GIF output through giflib: see image_files.hpp.
#include "image_files.hpp"

#include "errors.hpp"

#include <gif_lib.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <vector>

namespace jostle::cli {

namespace {

std::string gifMessage(int error) {
    const char* text = GifErrorString(error);
    return text ? text : "giflib error " + std::to_string(error);
}

/// The smallest power of two >= count (GIF colour tables come in those sizes), >= 2.
int colourTableSize(std::size_t count) {
    int size = 2;
    while (static_cast<std::size_t>(size) < count)
        size *= 2;
    return size;
}

} // namespace

GifWriter::~GifWriter() {
    if (gif_)
        EGifCloseFile(gif_, nullptr);
    if (file_)
        std::fclose(file_);
}

int GifWriter::write(GifFileType* gif, const GifByteType* bytes, int length) {
    auto* self = static_cast<GifWriter*>(gif->UserData);
    errno = 0;
    const std::size_t written =
        std::fwrite(bytes, 1, static_cast<std::size_t>(length), self->file_);
    if (written != static_cast<std::size_t>(length) && self->error_ == 0)
        self->error_ = errno != 0 ? errno : EIO;
    return static_cast<int>(written);
}

std::string GifWriter::failure(int gifError) const {
    return error_ != 0 ? systemMessage(error_) : gifMessage(gifError);
}

std::string GifWriter::open(const std::string& path, int width, int height,
                            std::span<const Rgb> palette) {
    if (palette.empty() || palette.size() > 256)
        return "a GIF palette holds 1 to 256 colours";
    // A file of ours, written through giflib's output function, so that a write that
    // fails keeps its errno; and created 0666 & ~umask, as an image to share is, where
    // EGifOpenFileName makes it readable by its owner only.
    errno = 0;
    file_ = std::fopen(path.c_str(), "wb");
    if (!file_)
        return systemMessage(errno);
    int error = 0;
    gif_ = EGifOpen(this, &GifWriter::write, &error);
    if (!gif_)
        return gifMessage(error);
    EGifSetGifVersion(gif_, true); // GIF89a: needed for delays and looping

    std::vector<GifColorType> colours(static_cast<std::size_t>(colourTableSize(palette.size())));
    for (std::size_t i = 0; i < palette.size(); ++i)
        colours[i] = {palette[i].r, palette[i].g, palette[i].b};
    ColorMapObject* map = GifMakeMapObject(static_cast<int>(colours.size()), colours.data());
    if (!map)
        return "out of memory";
    const int written = EGifPutScreenDesc(gif_, width, height, map->BitsPerPixel, 0, map);
    GifFreeMapObject(map);
    if (written == GIF_ERROR)
        return failure(gif_->Error);

    // The NETSCAPE2.0 extension with a loop count of 0: play again and again.
    static const GifByteType kApplication[] = {'N', 'E', 'T', 'S', 'C', 'A',
                                               'P', 'E', '2', '.', '0'};
    static const GifByteType kLoopForever[] = {1, 0, 0};
    if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof kApplication, kApplication) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof kLoopForever, kLoopForever) == GIF_ERROR ||
        EGifPutExtensionTrailer(gif_) == GIF_ERROR)
        return failure(gif_->Error);
    return {};
}

std::string GifWriter::addFrame(const Canvas& canvas, int delayCentiseconds) {
    // Only the rectangle that changed since the last frame (all of the first), drawn over
    // what that frame left (DISPOSE_DO_NOT): what is shown is the whole canvas, in a file
    // a fraction of the size. A frame like the last is one pixel.
    int x0 = 0;
    int y0 = 0;
    int x1 = canvas.width();
    int y1 = canvas.height();
    if (!last_.empty()) {
        x0 = canvas.width();
        y0 = canvas.height();
        x1 = 0;
        y1 = 0;
        for (int y = 0; y < canvas.height(); ++y) {
            const auto row = canvas.row(y);
            const auto* before = last_.data() + static_cast<std::size_t>(y) * row.size();
            for (int x = 0; x < canvas.width(); ++x)
                if (row[static_cast<std::size_t>(x)] != before[x]) {
                    x0 = std::min(x0, x);
                    x1 = std::max(x1, x + 1);
                    y0 = std::min(y0, y);
                    y1 = y + 1;
                }
        }
        if (x1 == 0) {
            x0 = 0;
            y0 = 0;
            x1 = 1;
            y1 = 1;
        }
    }
    last_.clear();
    for (int y = 0; y < canvas.height(); ++y) {
        const auto row = canvas.row(y);
        last_.insert(last_.end(), row.begin(), row.end());
    }

    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.DelayTime = delayCentiseconds;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const auto length = EGifGCBToExtension(&control, extension);
    if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) ==
            GIF_ERROR ||
        EGifPutImageDesc(gif_, x0, y0, x1 - x0, y1 - y0, false, nullptr) == GIF_ERROR)
        return failure(gif_->Error);
    std::vector<GifPixelType> line;
    for (int y = y0; y < y1; ++y) {
        const auto row =
            canvas.row(y).subspan(static_cast<std::size_t>(x0), static_cast<std::size_t>(x1 - x0));
        line.assign(row.begin(), row.end()); // giflib wants a writable line
        if (EGifPutLine(gif_, line.data(), x1 - x0) == GIF_ERROR)
            return failure(gif_->Error);
    }
    return {};
}

std::string GifWriter::close() {
    int error = 0;
    const int closed = EGifCloseFile(gif_, &error); // writes the trailer; leaves file_ open
    gif_ = nullptr;                                 // closed or not, giflib has freed it
    errno = 0;
    if (std::fclose(file_) != 0 && error_ == 0)
        error_ = errno != 0 ? errno : EIO;
    file_ = nullptr;
    if (error_ != 0)
        return systemMessage(error_);
    return closed == GIF_ERROR ? gifMessage(error) : std::string();
}

} // namespace jostle::cli
