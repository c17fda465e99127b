// Checks a screenshot of jostle-demo: the BMP file can be read and is not one colour
// (a window that drew nothing, or a black frame read back too late, is one colour).
// Exits 0 if it passes, 1 with the reason otherwise.
#include <SDL.h>

#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: check_screenshot FILE.bmp\n");
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
    const auto* bytes = static_cast<const unsigned char*>(image->pixels);
    Uint32 first = 0;
    std::memcpy(&first, bytes, sizeof first);
    long differing = 0;
    for (int y = 0; y < image->h; ++y)
        for (int x = 0; x < image->w; ++x) {
            Uint32 pixel = 0;
            std::memcpy(&pixel, bytes + y * image->pitch + x * 4, sizeof pixel);
            differing += pixel != first ? 1 : 0;
        }
    std::printf("%s: %dx%d, %ld pixels differ from the top-left one\n", argv[1], image->w, image->h,
                differing);
    SDL_FreeSurface(image);
    if (differing == 0) {
        std::fprintf(stderr, "%s: the screenshot is a single colour\n", argv[1]);
        return 1;
    }
    return 0;
}
