// Debug drawing with SDL: see sdl_draw.hpp.
#include "sdl_draw.hpp"

#include "shared/drawn_shape.hpp"

#include <algorithm>
#include <vector>

namespace jostle::demo {

namespace {

/// The most points a quarter of a rounded body's edge is drawn with.
constexpr int kMostArcPoints = 24;

SDL_Color sdl(Colour c) {
    return {c.r, c.g, c.b, c.a};
}

} // namespace

void SdlDraw::setColour(Colour colour) {
    SDL_SetRenderDrawColor(renderer_, colour.r, colour.g, colour.b, colour.a);
}

void SdlDraw::line(Vec2 from, Vec2 to, Colour colour) {
    const SDL_Point a = view_.toScreen(from), b = view_.toScreen(to);
    setColour(colour);
    SDL_RenderDrawLine(renderer_, a.x, a.y, b.x, b.y);
}

void SdlDraw::box(Vec2 centre, Vec2 half, Colour fill, Colour outline) {
    const SDL_Rect rect = view_.toScreen(centre, half);
    if (fill.a != 0) {
        setColour(fill);
        SDL_RenderFillRect(renderer_, &rect);
    }
    setColour(outline);
    SDL_RenderDrawRect(renderer_, &rect);
}

void SdlDraw::roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) {
    // Arcs of a point every 2 pixels or so, 3 to 24 points a quarter.
    const int arcPoints =
        std::clamp(static_cast<int>(radius * view_.scale() / 2.0f) + 2, 3, kMostArcPoints);
    const shared::DrawnShape shape{shared::DrawnKind::Rounded, centre, half, radius, {}};
    std::vector<SDL_FPoint> points;
    for (const Vec2 point : shape.perimeter(arcPoints))
        points.push_back(view_.toScreenExact(point));
    points.push_back(points.front());
    if (fill.a != 0) {
        const SDL_FPoint middle = view_.toScreenExact(centre);
        std::vector<SDL_Vertex> fan;
        fan.reserve(3 * (points.size() - 1));
        for (std::size_t i = 0; i + 1 < points.size(); ++i)
            for (const SDL_FPoint& p : {middle, points[i], points[i + 1]})
                fan.push_back({p, sdl(fill), {0.0f, 0.0f}});
        SDL_RenderGeometry(renderer_, nullptr, fan.data(), static_cast<int>(fan.size()), nullptr,
                           0);
    }
    setColour(outline);
    SDL_RenderDrawLinesF(renderer_, points.data(), static_cast<int>(points.size()));
}

void SdlDraw::triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) {
    const SDL_FPoint points[] = {view_.toScreenExact(a), view_.toScreenExact(b),
                                 view_.toScreenExact(c), view_.toScreenExact(a)};
    if (fill.a != 0) {
        const SDL_Vertex corners[] = {{points[0], sdl(fill), {0.0f, 0.0f}},
                                      {points[1], sdl(fill), {0.0f, 0.0f}},
                                      {points[2], sdl(fill), {0.0f, 0.0f}}};
        SDL_RenderGeometry(renderer_, nullptr, corners, 3, nullptr, 0);
    }
    setColour(outline);
    SDL_RenderDrawLinesF(renderer_, points, 4);
}

void SdlDraw::point(Vec2 at, float, Colour colour) {
    const SDL_Point p = view_.toScreen(at);
    const SDL_Rect dot{p.x - 1, p.y - 1, 3, 3};
    setColour(colour);
    SDL_RenderFillRect(renderer_, &dot);
}

} // namespace jostle::demo
