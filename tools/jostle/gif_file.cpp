// Animated GIF output through giflib: see image_files.hpp.
#include "image_files.hpp"

#include "errors.hpp"

#include <gif_lib.h>

#include <fcntl.h>

#include <cerrno>
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
}

std::string GifWriter::open(const std::string& path, int width, int height,
                            std::span<const Rgb> palette) {
    if (palette.empty() || palette.size() > 256)
        return "a GIF palette holds 1 to 256 colours";
    int error = 0;
    // Opened here rather than by EGifOpenFileName, which makes the file readable by its
    // owner only: an image is made to be shared, so it gets the usual 0666 & ~umask.
    const int descriptor = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0666);
    if (descriptor < 0)
        return systemMessage(errno);
    gif_ = EGifOpenFileHandle(descriptor, &error); // closes the descriptor if it fails
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
        return gifMessage(gif_->Error);

    // The NETSCAPE2.0 extension with a loop count of 0: play again and again.
    static const GifByteType kApplication[] = {'N', 'E', 'T', 'S', 'C', 'A',
                                               'P', 'E', '2', '.', '0'};
    static const GifByteType kLoopForever[] = {1, 0, 0};
    if (EGifPutExtensionLeader(gif_, APPLICATION_EXT_FUNC_CODE) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof kApplication, kApplication) == GIF_ERROR ||
        EGifPutExtensionBlock(gif_, sizeof kLoopForever, kLoopForever) == GIF_ERROR ||
        EGifPutExtensionTrailer(gif_) == GIF_ERROR)
        return gifMessage(gif_->Error);
    return {};
}

std::string GifWriter::addFrame(const Canvas& canvas, int delayCentiseconds) {
    GraphicsControlBlock control{};
    control.DisposalMode = DISPOSE_DO_NOT;
    control.DelayTime = delayCentiseconds;
    control.TransparentColor = NO_TRANSPARENT_COLOR;
    GifByteType extension[4];
    const auto length = EGifGCBToExtension(&control, extension);
    if (EGifPutExtension(gif_, GRAPHICS_EXT_FUNC_CODE, static_cast<int>(length), extension) ==
            GIF_ERROR ||
        EGifPutImageDesc(gif_, 0, 0, canvas.width(), canvas.height(), false, nullptr) == GIF_ERROR)
        return gifMessage(gif_->Error);
    std::vector<GifPixelType> line(static_cast<std::size_t>(canvas.width()));
    for (int y = 0; y < canvas.height(); ++y) {
        const auto row = canvas.row(y);
        line.assign(row.begin(), row.end()); // giflib wants a writable line
        if (EGifPutLine(gif_, line.data(), canvas.width()) == GIF_ERROR)
            return gifMessage(gif_->Error);
    }
    return {};
}

std::string GifWriter::close() {
    int error = 0;
    const int closed = EGifCloseFile(gif_, &error);
    gif_ = nullptr; // closed or not, giflib has freed it
    return closed == GIF_ERROR ? gifMessage(error) : std::string();
}

} // namespace jostle::cli
