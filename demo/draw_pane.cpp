// Drawing a pane: see draw_pane.hpp.
#include "draw_pane.hpp"

#include "draw_contacts.hpp"
#include "font.hpp"
#include "grid_picture.hpp"
#include "palette.hpp"

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
/// Velocity lines: seconds of motion they show, so their length reads as speed.
constexpr float kVelocitySeconds = 0.1f;
/// The legend and the grid's caption: small, under the pane's title.
constexpr int kLegendScale = 1;
constexpr int kLegendTop = kTitleHeight + 4;
constexpr int kLegendLineHeight = kGlyphHeight + 4;

void drawBody(SDL_Renderer* renderer, const World& world, BodyId body, const View& view,
              bool debug) {
    const Vec2 centre = world.position(body);
    const Vec2 half = world.halfExtents(body);
    const SDL_Rect rect = view.toScreen(centre, half);
    const BodyType type = world.type(body);
    SDL_Color colour = kTypeColours[static_cast<std::size_t>(type)];
    if (debug && type != BodyType::Static && !world.isAwake(body))
        colour = scaled(colour, kSleepingPercent);

    if (world.isSensor(body)) {
        setColour(renderer, colour);
        SDL_RenderDrawRect(renderer, &rect);
        return;
    }
    setColour(renderer, colour);
    SDL_RenderFillRect(renderer, &rect);
    setColour(renderer, world.isBullet(body) ? kBulletOutline : scaled(colour, kOutlinePercent));
    SDL_RenderDrawRect(renderer, &rect);
    // A one-way platform: its blocking face drawn bright, so one can see which it is.
    const Vec2 normal = world.oneWay(body);
    if (normal.x != 0.0f || normal.y != 0.0f) {
        // The face the normal points out of: along x for a vertical normal, else along y.
        const Vec2 face = centre + Vec2{normal.x * half.x, normal.y * half.y};
        const Vec2 along = normal.y != 0.0f ? Vec2{half.x, 0.0f} : Vec2{0.0f, half.y};
        const SDL_Point a = view.toScreen(face - along);
        const SDL_Point b = view.toScreen(face + along);
        setColour(renderer, kText);
        SDL_RenderDrawLine(renderer, a.x, a.y, b.x, b.y);
    }
    if (!debug || type != BodyType::Dynamic)
        return;

    // The sides the body touched in the last step, as red edges.
    const Touching touching = world.touching(body);
    setColour(renderer, kTouching);
    const int left = rect.x;
    const int top = rect.y;
    const int right = rect.x + rect.w - 1;
    const int bottom = rect.y + rect.h - 1;
    if (touching.floor)
        SDL_RenderDrawLine(renderer, left, bottom, right, bottom);
    if (touching.ceiling)
        SDL_RenderDrawLine(renderer, left, top, right, top);
    if (touching.wallLeft)
        SDL_RenderDrawLine(renderer, left, top, left, bottom);
    if (touching.wallRight)
        SDL_RenderDrawLine(renderer, right, top, right, bottom);
    if (world.isAwake(body)) {
        const SDL_Point from = view.toScreen(centre);
        const SDL_Point to = view.toScreen(centre + world.velocity(body) * kVelocitySeconds);
        setColour(renderer, kVelocity);
        SDL_RenderDrawLine(renderer, from.x, from.y, to.x, to.y);
    }
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
    const SDL_Color dimmed =
        scaled(kTypeColours[static_cast<std::size_t>(BodyType::Dynamic)], kSleepingPercent);
    const std::pair<SDL_Color, const char*> words[] = {
        {kContact, "contacts  "}, {kTouching, "sides touched  "}, {kVelocity, "velocity  "},
        {dimmed, "asleep  "},     {kGrownBox, "grown boxes  "},   {kGridCellOutline, "grid cells"},
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

    const World& world = *pane.world;
    GridPicture grid;
    if (debug) {
        grid = pictureGrid(world, dt);
        drawGridPicture(renderer, grid, view);
    }
    for (BodyId body : world.bodies())
        drawBody(renderer, world, body, view, debug);

    if (debug)
        drawContacts(renderer, world, pane.contacts, view);

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
