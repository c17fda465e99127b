// PNG output through libpng's simplified API: see image_files.hpp.
#include "image_files.hpp"

#include <png.h>

#include <vector>

namespace jostle::cli {

std::string writePng(std::FILE* file, const Canvas& canvas, std::span<const Rgb> palette) {
    std::vector<std::uint8_t> rgb;
    rgb.reserve(static_cast<std::size_t>(canvas.width()) *
                static_cast<std::size_t>(canvas.height()) * 3);
    for (int y = 0; y < canvas.height(); ++y)
        for (std::uint8_t index : canvas.row(y)) {
            const Rgb colour = palette[index];
            rgb.insert(rgb.end(), {colour.r, colour.g, colour.b});
        }

    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(canvas.width());
    image.height = static_cast<png_uint_32>(canvas.height());
    image.format = PNG_FORMAT_RGB;
    const int ok = png_image_write_to_stdio(&image, file, 0, rgb.data(), 0, nullptr);
    std::string error = ok ? "" : image.message;
    png_image_free(&image);
    return error;
}

} // namespace jostle::cli
