// Where debug drawing puts a touching pair's contact: see drawn_contact.hpp.
#include "drawn_contact.hpp"

#include <algorithm>

namespace jostle::demo {

namespace {

/// The middle of the overlap of [lowA, highA] and [lowB, highB], or of the gap between.
float middleOfShared(float lowA, float highA, float lowB, float highB) {
    return (std::max(lowA, lowB) + std::min(highA, highB)) / 2.0f;
}

} // namespace

Vec2 contactPoint(const World& world, const TouchingPair& pair) {
    const Vec2 ca = world.position(pair.a), ha = world.halfExtents(pair.a);
    const Vec2 cb = world.position(pair.b), hb = world.halfExtents(pair.b);
    const Vec2 n = pair.normal;
    // b lies on a's side opposite the normal: a's face there is at ca - n·ha, b's facing
    // one at cb + n·hb.
    if (n.y != 0.0f)
        return {middleOfShared(ca.x - ha.x, ca.x + ha.x, cb.x - hb.x, cb.x + hb.x),
                ((ca.y - n.y * ha.y) + (cb.y + n.y * hb.y)) / 2.0f};
    return {((ca.x - n.x * ha.x) + (cb.x + n.x * hb.x)) / 2.0f,
            middleOfShared(ca.y - ha.y, ca.y + ha.y, cb.y - hb.y, cb.y + hb.y)};
}

DrawnContact drawnContact(const World& world, const TouchingPair& pair) {
    if (pair.normal.x == 0.0f || pair.normal.y == 0.0f)
        return {contactPoint(world, pair), pair.normal};
    for (const ContactInfo& contact : world.contacts(pair.a))
        if (contact.other == pair.b)
            return {contact.point, contact.normal};
    return {contactPoint(world, pair), pair.normal}; // apart since the events were read
}

} // namespace jostle::demo
