// Saving screenshots: see screenshot.hpp.
#include "screenshot.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#if JOSTLE_DEMO_PNG
#include <png.h>
#endif

namespace jostle::demo {

bool isPngName(const std::string& path) {
    const std::string suffix = ".png";
    if (path.size() < suffix.size())
        return false;
    return std::equal(suffix.rbegin(), suffix.rend(), path.rbegin(), [](char a, char b) {
        return a == std::tolower(static_cast<unsigned char>(b));
    });
}

bool canWritePng() {
    return JOSTLE_DEMO_PNG != 0;
}

std::string saveScreenshot(SDL_Renderer* renderer, int width, int height, const std::string& path) {
    if (isPngName(path)) {
#if JOSTLE_DEMO_PNG
        // Three bytes a pixel, red first: what a PNG of RGB rows holds.
        const int pitch = 3 * width;
        std::vector<unsigned char> rgb(static_cast<std::size_t>(pitch) *
                                       static_cast<std::size_t>(height));
        const SDL_Rect all{0, 0, width, height};
        if (SDL_RenderReadPixels(renderer, &all, SDL_PIXELFORMAT_RGB24, rgb.data(), pitch) != 0)
            return SDL_GetError();
        png_image image{};
        image.version = PNG_IMAGE_VERSION;
        image.width = static_cast<png_uint_32>(width);
        image.height = static_cast<png_uint_32>(height);
        image.format = PNG_FORMAT_RGB;
        if (png_image_write_to_file(&image, path.c_str(), 0, rgb.data(), pitch, nullptr) == 0)
            return image.message;
        return {};
#else
        return "this jostle-demo was built without libpng: save a .bmp";
#endif
    }
    SDL_Surface* surface =
        SDL_CreateRGBSurfaceWithFormat(0, width, height, 32, SDL_PIXELFORMAT_ARGB8888);
    if (surface == nullptr)
        return SDL_GetError();
    const SDL_Rect all{0, 0, width, height};
    const bool saved = SDL_RenderReadPixels(renderer, &all, SDL_PIXELFORMAT_ARGB8888,
                                            surface->pixels, surface->pitch) == 0 &&
                       SDL_SaveBMP(surface, path.c_str()) == 0;
    SDL_FreeSurface(surface);
    return saved ? std::string() : std::string(SDL_GetError());
}

} // namespace jostle::demo
