// Checks a screenshot of jostle-demo.
//
//   check_screenshot FILE.bmp
//       the BMP file can be read and is not one colour (a window that drew nothing, or
//       a black frame read back too late, is one colour); exits 0 if it passes, 1 with
//       the reason otherwise.
//   check_screenshot FILE.bmp --count RRGGBB X0 Y0 X1 Y1
//       prints how many pixels of the rectangle from (X0, Y0) to (X1, Y1), both
//       included, are exactly that colour, so that a test can tell where something was
//       drawn (debug marks are drawn opaque in colours of their own for this).
#include <SDL.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace {

Uint32 pixelAt(const SDL_Surface* image, int x, int y) {
    Uint32 pixel = 0;
    std::memcpy(&pixel, static_cast<const unsigned char*>(image->pixels) + y * image->pitch + x * 4,
                sizeof pixel);
    return pixel & 0x00FFFFFFu; // the colour: whatever the file says of alpha does not count
}

int checkNotOneColour(const char* path, const SDL_Surface* image) {
    const Uint32 first = pixelAt(image, 0, 0);
    long differing = 0;
    for (int y = 0; y < image->h; ++y)
        for (int x = 0; x < image->w; ++x)
            differing += pixelAt(image, x, y) != first ? 1 : 0;
    std::printf("%s: %dx%d, %ld pixels differ from the top-left one\n", path, image->w, image->h,
                differing);
    if (differing == 0) {
        std::fprintf(stderr, "%s: the screenshot is a single colour\n", path);
        return 1;
    }
    return 0;
}

int countColour(const char* path, const SDL_Surface* image, char** args) {
    char* end = nullptr;
    const unsigned long colour = std::strtoul(args[0], &end, 16);
    if (std::strlen(args[0]) != 6 || *end != '\0') {
        std::fprintf(stderr, "%s: not a colour RRGGBB: %s\n", path, args[0]);
        return 1;
    }
    int corners[4];
    for (int i = 0; i < 4; ++i)
        corners[i] = std::atoi(args[i + 1]);
    const auto [x0, y0, x1, y1] = corners;
    if (x0 < 0 || y0 < 0 || x1 >= image->w || y1 >= image->h || x0 > x1 || y0 > y1) {
        std::fprintf(stderr, "%s: the rectangle (%d, %d)-(%d, %d) is not inside %dx%d\n", path, x0,
                     y0, x1, y1, image->w, image->h);
        return 1;
    }
    long count = 0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x)
            count += pixelAt(image, x, y) == colour ? 1 : 0;
    std::printf("%ld\n", count);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const bool count = argc == 8 && std::string(argv[2]) == "--count";
    if (argc != 2 && !count) {
        std::fprintf(stderr, "usage: check_screenshot FILE.bmp [--count RRGGBB X0 Y0 X1 Y1]\n");
        return 1;
    }
    SDL_Surface* loaded = SDL_LoadBMP(argv[1]);
    if (loaded == nullptr) {
        std::fprintf(stderr, "%s: cannot read: %s\n", argv[1], SDL_GetError());
        return 1;
    }
    // One pixel format whatever the file holds, so pixels compare as 32-bit words.
    SDL_Surface* image = SDL_ConvertSurfaceFormat(loaded, SDL_PIXELFORMAT_ARGB8888, 0);
    SDL_FreeSurface(loaded);
    if (image == nullptr) {
        std::fprintf(stderr, "%s: cannot convert: %s\n", argv[1], SDL_GetError());
        return 1;
    }
    const int status =
        count ? countColour(argv[1], image, argv + 3) : checkNotOneColour(argv[1], image);
    SDL_FreeSurface(image);
    return status;
}
