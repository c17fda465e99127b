// Drawing the touching pairs: see draw_contacts.hpp.
#include "draw_contacts.hpp"

#include "palette.hpp"

#include <algorithm>

namespace jostle::demo {

namespace {

/// A contact's dot is this many pixels on each side of its point: 3 × 3 in all.
constexpr int kDotRadius = 1;
/// The normal's line is this long, or half the pushed body's extent along it when that
/// is shorter, so that in a pile of small boxes it stays inside the box it pushes.
constexpr float kNormalPixels = 14.0f;
constexpr float kShortestNormalPixels = 3.0f;

} // namespace

void drawContacts(SDL_Renderer* renderer, const World& world, const ContactSet& contacts,
                  const View& view) {
    setColour(renderer, kContact);
    contacts.forEach(world, [&](const TouchingPair& pair) {
        const DrawnContact contact = drawnContact(world, pair);
        const SDL_Point at = view.toScreen(contact.point);
        const SDL_Rect dot{at.x - kDotRadius, at.y - kDotRadius, 2 * kDotRadius + 1,
                           2 * kDotRadius + 1};
        SDL_RenderFillRect(renderer, &dot);
        // The normal points from b towards a. Drawn into the body it pushes: a, unless a
        // is a static or kinematic body that no contact moves (a floor made first); then
        // the other way, into b.
        const bool intoA = world.type(pair.a) == BodyType::Dynamic;
        const BodyId pushed = intoA ? pair.a : pair.b;
        const Vec2 direction = intoA ? contact.normal : -contact.normal;
        const Vec2 half = world.halfExtents(pushed);
        const float along = direction.y == 0.0f   ? half.x
                            : direction.x == 0.0f ? half.y
                                                  : std::min(half.x, half.y);
        const float extent = along * view.scale();
        const float pixels = std::clamp(extent, kShortestNormalPixels, kNormalPixels);
        SDL_RenderDrawLine(renderer, at.x, at.y, at.x + static_cast<int>(direction.x * pixels),
                           at.y + static_cast<int>(direction.y * pixels));
    });
}

} // namespace jostle::demo
