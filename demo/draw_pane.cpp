// Drawing a pane: see draw_pane.hpp.
#include "draw_pane.hpp"

#include "draw_contacts.hpp"
#include "draw_grid_picture.hpp"
#include "font.hpp"
#include "grid_picture.hpp"
#include "palette.hpp"

#include "shared/drawn_shape.hpp"

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
/// Velocity lines: seconds of motion they show, so their length reads as speed.
constexpr float kVelocitySeconds = 0.1f;
/// The legend and the grid's caption: small, under the pane's title.
constexpr int kLegendScale = 1;
constexpr int kLegendTop = kTitleHeight + 4;
constexpr int kLegendLineHeight = kGlyphHeight + 4;
/// The most points a quarter of a rounded body's edge is drawn with.
constexpr int kMostArcPoints = 24;

/// The points of a shape's perimeter on the screen, the first again at the end when it
/// is closed (all but a segment).
std::vector<SDL_FPoint> screenPerimeter(const shared::DrawnShape& shape, const View& view) {
    // Arcs of a point every 2 pixels or so, 3 to 24 points a quarter.
    const int arcPoints =
        std::clamp(static_cast<int>(shape.radius * view.scale() / 2.0f) + 2, 3, kMostArcPoints);
    std::vector<SDL_FPoint> points;
    for (const Vec2 point : shape.perimeter(arcPoints))
        points.push_back(view.toScreenExact(point));
    if (shape.kind != shared::DrawnKind::Segment)
        points.push_back(points.front());
    return points;
}

/// A rounded body or a ramp, filled (a fan of triangles from the middle of its convex
/// perimeter) unless it is a sensor, and outlined; a segment as a line, with a tick from
/// its middle towards the side it blocks.
void drawShape(SDL_Renderer* renderer, const shared::DrawnShape& shape, const View& view,
               SDL_Color fill, SDL_Color outline, bool sensor) {
    const std::vector<SDL_FPoint> points = screenPerimeter(shape, view);
    const int count = static_cast<int>(points.size());
    if (shape.kind == shared::DrawnKind::Segment) {
        const SDL_FPoint a = points[0];
        const SDL_FPoint b = points[1];
        const SDL_FPoint middle{(a.x + b.x) / 2.0f, (a.y + b.y) / 2.0f};
        const float tick = std::clamp(std::hypot(b.x - a.x, b.y - a.y) / 6.0f, 3.0f, 8.0f);
        const Vec2 normal = shape.faceNormal();
        setColour(renderer, sensor ? outline : fill);
        SDL_RenderDrawLineF(renderer, a.x, a.y, b.x, b.y);
        SDL_RenderDrawLineF(renderer, middle.x, middle.y, middle.x + normal.x * tick,
                            middle.y + normal.y * tick);
        return;
    }
    if (!sensor) {
        const SDL_FPoint centre = view.toScreenExact(shape.centre);
        std::vector<SDL_Vertex> fan;
        fan.reserve(static_cast<std::size_t>(3 * (count - 1)));
        for (int i = 0; i + 1 < count; ++i)
            for (const SDL_FPoint& p : {centre, points[i], points[i + 1]})
                fan.push_back({p, fill, {0.0f, 0.0f}});
        SDL_RenderGeometry(renderer, nullptr, fan.data(), static_cast<int>(fan.size()), nullptr, 0);
    }
    setColour(renderer, outline);
    SDL_RenderDrawLinesF(renderer, points.data(), count);
}

/// An awake body's velocity, as a line from its centre: a tenth of a second of its motion.
void drawVelocity(SDL_Renderer* renderer, const World& world, BodyId body, const View& view) {
    if (!world.isAwake(body))
        return;
    const Vec2 centre = world.position(body);
    const SDL_Point from = view.toScreen(centre);
    const SDL_Point to = view.toScreen(centre + world.velocity(body) * kVelocitySeconds);
    setColour(renderer, kVelocity);
    SDL_RenderDrawLine(renderer, from.x, from.y, to.x, to.y);
}

void drawBody(SDL_Renderer* renderer, const World& world, BodyId body, const View& view,
              bool debug) {
    const Vec2 centre = world.position(body);
    const Vec2 half = world.halfExtents(body);
    const SDL_Rect rect = view.toScreen(centre, half);
    const BodyType type = world.type(body);
    SDL_Color colour = kTypeColours[static_cast<std::size_t>(type)];
    if (debug && type != BodyType::Static && !world.isAwake(body))
        colour = scaled(colour, kSleepingPercent);
    const SDL_Color outline =
        world.isBullet(body) ? kBulletOutline : scaled(colour, kOutlinePercent);

    // Rounded bodies, ramps and segments in their shape (World::bodyDef has it).
    const shared::DrawnShape shape = shared::DrawnShape::of(world, body);
    if (shape.kind != shared::DrawnKind::Box) {
        const bool sensor = world.isSensor(body);
        drawShape(renderer, shape, view, colour, sensor ? colour : outline, sensor);
        if (debug && !sensor && type == BodyType::Dynamic)
            drawVelocity(renderer, world, body, view);
        return;
    }

    if (world.isSensor(body)) {
        setColour(renderer, colour);
        SDL_RenderDrawRect(renderer, &rect);
        return;
    }
    setColour(renderer, colour);
    SDL_RenderFillRect(renderer, &rect);
    setColour(renderer, outline);
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
    drawVelocity(renderer, world, body, view);
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
