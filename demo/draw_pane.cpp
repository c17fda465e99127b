// Drawing a pane: see draw_pane.hpp.
#include "draw_pane.hpp"

#include "font.hpp"
#include "grid_picture.hpp"
#include "palette.hpp"
#include "sdl_draw.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace jostle::demo {

namespace {

constexpr int kTextScale = 2;
/// The band at the top of a pane that holds its title: the world is drawn below it, so
/// that no body (a wall reaching above the view) is drawn across the title.
constexpr int kTitleHeight = 26;
constexpr int kTitleTop = 6;
/// Marks with no length of their own (a contact's normal, a segment's tick), in pixels.
constexpr float kMarkPixels = 14.0f;
/// The legend and the grid's caption: small, under the pane's title.
constexpr int kLegendScale = 1;
constexpr int kLegendTop = kTitleHeight + 4;
constexpr int kLegendLineHeight = kGlyphHeight + 4;

/// A colour of the library's palette as SDL's.
SDL_Color sdl(Colour c) {
    return {c.r, c.g, c.b, c.a};
}

/// The background under a line of legend text at (x, y), `width` pixels long, so that
/// what is drawn there (a wall, the grid) does not run through the words.
void drawPlate(SDL_Renderer* renderer, int x, int y, int width) {
    const SDL_Rect plate{x - 2, y - 2, width + 4, kGlyphHeight * kLegendScale + 4};
    setColour(renderer, kBackground);
    SDL_RenderFillRect(renderer, &plate);
}

/// What the debug marks mean, each word in its mark's colour, and which grid the
/// broadphase picture shows, with its main level's cell size.
void drawLegend(SDL_Renderer* renderer, const SDL_Rect& screen, const GridPicture& grid) {
    const DebugPalette palette;
    const SDL_Color dimmed = sdl(palette.fillOf(BodyType::Dynamic, true));
    const std::pair<SDL_Color, const char*> words[] = {
        {sdl(palette.contact), "contacts  "},     {sdl(palette.touching), "sides touched  "},
        {sdl(palette.velocity), "velocity  "},    {dimmed, "asleep  "},
        {sdl(palette.gridBox), "moving boxes  "}, {sdl(palette.gridCell), "grid cells"},
    };
    int x = screen.x + 8;
    const int y = screen.y + kLegendTop;
    int width = 0;
    for (const auto& [colour, word] : words)
        width += textWidth(kLegendScale, word);
    drawPlate(renderer, x, y, width);
    for (const auto& [colour, word] : words) {
        setColour(renderer, colour);
        x = drawText(renderer, x, y, kLegendScale, word);
    }
    std::string caption = "broadphase: no boxes";
    if (!grid.boxes.empty()) {
        char cell[32];
        std::snprintf(cell, sizeof cell, "%.3g", grid.cellSize(grid.mainLevel));
        caption = grid.name + " grid: " + std::to_string(grid.boxes.size()) +
                  (grid.boxes.size() == 1 ? " box, " : " boxes, ") +
                  std::to_string(grid.inMainLevel) + " in cells of " + cell + " (level " +
                  std::to_string(grid.mainLevel) + ")";
    }
    drawPlate(renderer, screen.x + 8, y + kLegendLineHeight, textWidth(kLegendScale, caption));
    setColour(renderer, kTextDim);
    drawText(renderer, screen.x + 8, y + kLegendLineHeight, kLegendScale, caption);
}

} // namespace

void drawPane(SDL_Renderer* renderer, const Pane& pane, const View& view, bool debug, float dt) {
    const SDL_Rect& screen = view.screen();
    SDL_RenderSetClipRect(renderer, &screen);
    setColour(renderer, kBackground);
    SDL_RenderFillRect(renderer, &screen);
    // The world, below the title's band.
    const SDL_Rect below{screen.x, screen.y + kTitleHeight, screen.w, screen.h - kTitleHeight};
    SDL_RenderSetClipRect(renderer, &below);

    // The world as the library draws it (paneDrawOptions: the page draws it alike).
    const World& world = *pane.world;
    const DebugDrawOptions options = paneDrawOptions(
        debug, kMarkPixels / view.scale(),
        {view.toWorld(below.x, below.y), view.toWorld(below.x + below.w, below.y + below.h)});
    SdlDraw draw(renderer, view);
    world.debugDraw(draw, options);
    const GridPicture grid = debug ? pictureGrid(world, dt) : GridPicture{};

    setColour(renderer, kText);
    for (const Label& label : pane.labels) {
        if (!world.isValid(label.body))
            continue;
        const SDL_Rect rect =
            view.toScreen(world.position(label.body), world.halfExtents(label.body));
        const int width = textWidth(1, label.text);
        drawText(renderer, rect.x + rect.w / 2 - width / 2, rect.y - kGlyphHeight - 4, 1,
                 label.text);
    }
    SDL_RenderSetClipRect(renderer, &screen);
    setColour(renderer, kTextDim);
    drawText(renderer, screen.x + 8, screen.y + kTitleTop, kTextScale, pane.title);
    setColour(renderer, kPaneBorder);
    SDL_RenderDrawLine(renderer, screen.x, below.y - 1, screen.x + screen.w - 1, below.y - 1);
    if (debug)
        drawLegend(renderer, screen, grid);
    setColour(renderer, kPaneBorder);
    SDL_RenderDrawRect(renderer, &screen);
    SDL_RenderSetClipRect(renderer, nullptr);
}

} // namespace jostle::demo
