// --screenshot: the window's pixels saved as a BMP (SDL's own) or, where the demo was
// built with libpng, a PNG, chosen by the file's name (docs/demo.md, Command line).
#pragma once

#include <SDL.h>

#include <string>

namespace jostle::demo {

/// Whether `path` names a PNG (ends in .png, any case); every other name is a BMP.
bool isPngName(const std::string& path);

/// Whether this build can write PNGs (libpng was found when it was configured).
bool canWritePng();

/// Saves what `renderer` has drawn, width × height pixels from the top left, to `path`:
/// a PNG when isPngName(path), else a BMP. Returns an empty string, or what went wrong.
std::string saveScreenshot(SDL_Renderer* renderer, int width, int height, const std::string& path);

} // namespace jostle::demo
