// Compares a picture in docs/ with the same picture drawn again, frame by frame and pixel
// by pixel, as decoded images (so that two encoders' different bytes for the same pixels
// do not count): an animated GIF's frames as a viewer shows them, a PNG as its one frame.
//
//   compare_pictures COMMITTED REDRAWN NAME
//
// Exits 0 when they are the same picture: as many frames, each of the same size, the same
// colour at every pixel and, in a GIF, shown for as long. Otherwise exits 1 and prints,
// naming the picture as NAME, the first frame that differs and where, how many frames
// differ, and that scripts/pictures.sh draws the pictures again. 2 when a file cannot be
// read.
#include <gif_lib.h>
#include <png.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

struct Frame {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb; ///< 3 bytes a pixel, row after row
    int delay = -1;                ///< a GIF frame's delay in centiseconds; -1 in a PNG

    std::uint32_t at(int x, int y) const {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                                   static_cast<std::size_t>(x));
        return (std::uint32_t{rgb[i]} << 16) | (std::uint32_t{rgb[i + 1]} << 8) | rgb[i + 2];
    }
};

struct Picture {
    std::vector<Frame> frames;
    std::string error; ///< why it could not be read, or empty
};

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Picture readPng(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (png_image_begin_read_from_file(&image, path.c_str()) == 0)
        return {{}, image.message};
    image.format = PNG_FORMAT_RGB;
    Frame frame;
    frame.width = static_cast<int>(image.width);
    frame.height = static_cast<int>(image.height);
    frame.rgb.resize(PNG_IMAGE_SIZE(image));
    if (png_image_finish_read(&image, nullptr, frame.rgb.data(), 0, nullptr) == 0)
        return {{}, image.message};
    return {{std::move(frame)}, {}};
}

/// Every frame of an animated GIF as a viewer shows it: each image drawn over what the
/// previous frame left (its disposal), its transparent colour showing what is under it.
Picture readGif(const std::string& path) {
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path.c_str(), &error);
    if (gif == nullptr)
        return {{}, GifErrorString(error)};
    Picture picture;
    if (DGifSlurp(gif) == GIF_ERROR) {
        picture.error = GifErrorString(gif->Error);
        DGifCloseFile(gif, &error);
        return picture;
    }
    const int width = gif->SWidth;
    const int height = gif->SHeight;
    std::vector<std::uint8_t> screen(3 * static_cast<std::size_t>(width) *
                                     static_cast<std::size_t>(height));
    const auto colourOf = [](const ColorMapObject* map, int index) -> std::optional<GifColorType> {
        if (map == nullptr || index < 0 || index >= map->ColorCount)
            return std::nullopt;
        return map->Colors[index];
    };
    if (const auto background = colourOf(gif->SColorMap, gif->SBackGroundColor))
        for (std::size_t i = 0; i < screen.size(); i += 3) {
            screen[i] = background->Red;
            screen[i + 1] = background->Green;
            screen[i + 2] = background->Blue;
        }
    for (int n = 0; n < gif->ImageCount && picture.error.empty(); ++n) {
        const SavedImage& image = gif->SavedImages[n];
        GraphicsControlBlock control{};
        control.DisposalMode = DISPOSAL_UNSPECIFIED;
        control.TransparentColor = NO_TRANSPARENT_COLOR;
        DGifSavedExtensionToGCB(gif, n, &control);
        const ColorMapObject* map =
            image.ImageDesc.ColorMap != nullptr ? image.ImageDesc.ColorMap : gif->SColorMap;
        const GifImageDesc& desc = image.ImageDesc;
        std::vector<std::uint8_t> before;
        if (control.DisposalMode == DISPOSE_PREVIOUS)
            before = screen;
        // The frame's colours by index, looked up once: a row is then a copy per pixel.
        std::array<GifColorType, 256> colours{};
        std::array<bool, 256> known{};
        for (int index = 0; index < 256; ++index)
            if (const auto colour = colourOf(map, index);
                colour && index != control.TransparentColor) {
                colours[static_cast<std::size_t>(index)] = *colour;
                known[static_cast<std::size_t>(index)] = true;
            }
        const int right = std::min(desc.Left + desc.Width, width);
        for (int y = 0; y < desc.Height && desc.Top + y < height; ++y) {
            const GifByteType* row = image.RasterBits + static_cast<std::ptrdiff_t>(y) * desc.Width;
            std::uint8_t* out = screen.data() + 3 * (static_cast<std::size_t>(desc.Top + y) *
                                                         static_cast<std::size_t>(width) +
                                                     static_cast<std::size_t>(desc.Left));
            for (int x = 0; x < right - desc.Left; ++x, out += 3) {
                const GifByteType index = row[x];
                if (!known[index]) {
                    if (index == control.TransparentColor)
                        continue;
                    picture.error = "frame " + std::to_string(n) + ": colour " +
                                    std::to_string(index) + " is not in its colour table";
                    break;
                }
                out[0] = colours[index].Red;
                out[1] = colours[index].Green;
                out[2] = colours[index].Blue;
            }
            if (!picture.error.empty())
                break;
        }
        picture.frames.push_back({width, height, screen, control.DelayTime});
        if (control.DisposalMode == DISPOSE_PREVIOUS)
            screen = before;
        else if (control.DisposalMode == DISPOSE_BACKGROUND) {
            const auto background = colourOf(gif->SColorMap, gif->SBackGroundColor);
            for (int y = desc.Top; y < std::min(desc.Top + desc.Height, height); ++y)
                for (int x = desc.Left; x < std::min(desc.Left + desc.Width, width); ++x) {
                    const std::size_t i =
                        3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                             static_cast<std::size_t>(x));
                    screen[i] = background ? background->Red : 0;
                    screen[i + 1] = background ? background->Green : 0;
                    screen[i + 2] = background ? background->Blue : 0;
                }
        }
    }
    DGifCloseFile(gif, &error);
    return picture;
}

Picture readPicture(const std::string& path) {
    if (endsWith(path, ".gif"))
        return readGif(path);
    if (endsWith(path, ".png"))
        return readPng(path);
    return {{}, "not a .gif or a .png"};
}

std::string hex(std::uint32_t colour) {
    char text[16];
    std::snprintf(text, sizeof text, "#%06x", static_cast<unsigned>(colour));
    return text;
}

/// How `committed` differs from `redrawn`, or empty when they are the same frame.
std::string difference(const Frame& committed, const Frame& redrawn) {
    if (committed.width != redrawn.width || committed.height != redrawn.height)
        return "it is " + std::to_string(committed.width) + " x " +
               std::to_string(committed.height) + " pixels, drawn now " +
               std::to_string(redrawn.width) + " x " + std::to_string(redrawn.height);
    if (committed.rgb == redrawn.rgb)
        return committed.delay == redrawn.delay
                   ? std::string()
                   : "it is shown for " + std::to_string(committed.delay) + " cs, drawn now for " +
                         std::to_string(redrawn.delay) + " cs";
    for (int y = 0; y < committed.height; ++y)
        for (int x = 0; x < committed.width; ++x)
            if (committed.at(x, y) != redrawn.at(x, y)) {
                long count = 0;
                for (std::size_t i = 0; i < committed.rgb.size(); i += 3)
                    count += std::equal(committed.rgb.begin() + static_cast<long>(i),
                                        committed.rgb.begin() + static_cast<long>(i) + 3,
                                        redrawn.rgb.begin() + static_cast<long>(i))
                                 ? 0
                                 : 1;
                return std::to_string(count) + " pixels differ, the first at (" +
                       std::to_string(x) + ", " + std::to_string(y) +
                       "): " + hex(committed.at(x, y)) + " in the file, " + hex(redrawn.at(x, y)) +
                       " drawn now";
            }
    return {}; // not reached: the pixels differ somewhere
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: compare_pictures COMMITTED REDRAWN NAME\n");
        return 2;
    }
    const std::string name = argv[3];
    const Picture committed = readPicture(argv[1]);
    const Picture redrawn = readPicture(argv[2]);
    for (const auto& [picture, path] : {std::pair{&committed, argv[1]}, {&redrawn, argv[2]}})
        if (!picture->error.empty()) {
            std::printf("%s: cannot read %s: %s\n", name.c_str(), path, picture->error.c_str());
            return 2;
        }

    const std::size_t frames = std::min(committed.frames.size(), redrawn.frames.size());
    std::size_t differing = 0;
    std::optional<std::size_t> first;
    std::string firstDifference;
    for (std::size_t i = 0; i < frames; ++i) {
        const std::string what = difference(committed.frames[i], redrawn.frames[i]);
        if (what.empty())
            continue;
        ++differing;
        if (!first) {
            first = i;
            firstDifference = what;
        }
    }
    const bool sameCount = committed.frames.size() == redrawn.frames.size();
    if (!first && sameCount) {
        std::printf("%s: the same as drawn now (%zu frame%s)\n", name.c_str(), frames,
                    frames == 1 ? "" : "s");
        return 0;
    }
    std::printf("FAIL: %s is not what scripts/pictures.sh draws now:\n", name.c_str());
    if (!sameCount)
        std::printf("  it has %zu frames, drawn now %zu\n", committed.frames.size(),
                    redrawn.frames.size());
    if (first) {
        if (frames == 1)
            std::printf("  %s\n", firstDifference.c_str());
        else
            std::printf("  frame %zu (counting from 0) is the first that differs: %s; %zu of "
                        "the %zu frames both have differ\n",
                        *first, firstDifference.c_str(), differing, frames);
    }
    std::printf("  The picture is stale: run scripts/pictures.sh, look at it and commit it.\n");
    return 1;
}
