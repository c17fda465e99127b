// World::debugDraw and DebugDraw's lines: see jostle/debug_draw.hpp, docs/debug-draw.md.
#include "jostle/debug_draw.hpp"

#include "ground.hpp"
#include "jostle/query.hpp"
#include "shapes.hpp"
#include "world_access.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace jostle {

// --- The default drawings: lines ---------------------------------------------------------

void DebugDraw::box(Vec2 centre, Vec2 half, Colour, Colour outline) {
    const Vec2 a = centre - half, c = centre + half;
    const Vec2 b{c.x, a.y}, d{a.x, c.y};
    line(a, b, outline);
    line(b, c, outline);
    line(c, d, outline);
    line(d, a, outline);
}

void DebugDraw::roundedBox(Vec2 centre, Vec2 half, float radius, Colour, Colour outline) {
    constexpr int kArcLines = 6;
    const Vec2 core = half - Vec2{radius, radius};
    const std::array<Vec2, 4> corners{
        {{core.x, core.y}, {-core.x, core.y}, {-core.x, -core.y}, {core.x, -core.y}}};
    // Round the box: each corner's arc, then the straight side to the next arc.
    Vec2 previous = centre + Vec2{half.x, -core.y};
    for (int corner = 0; corner < 4; ++corner)
        for (int i = 0; i <= kArcLines; ++i) {
            const double angle = (corner + double(i) / kArcLines) * std::numbers::pi / 2.0;
            const Vec2 next = centre + corners[std::size_t(corner)] +
                              Vec2{float(std::cos(angle)), float(std::sin(angle))} * radius;
            if (next != previous)
                line(previous, next, outline);
            previous = next;
        }
}

void DebugDraw::triangle(Vec2 a, Vec2 b, Vec2 c, Colour, Colour outline) {
    line(a, b, outline);
    line(b, c, outline);
    line(c, a, outline);
}

void DebugDraw::point(Vec2 at, float size, Colour colour) {
    const float h = size / 2.0f;
    line(at - Vec2{h, 0.0f}, at + Vec2{h, 0.0f}, colour);
    line(at - Vec2{0.0f, h}, at + Vec2{0.0f, h}, colour);
}

// --- The list -----------------------------------------------------------------------------

void DebugDrawList::line(Vec2 from, Vec2 to, Colour colour) {
    commands_.push_back({{from.x, from.y, to.x, to.y}, colour, colour, Kind::Line});
}

void DebugDrawList::box(Vec2 centre, Vec2 half, Colour fill, Colour outline) {
    commands_.push_back({{centre.x, centre.y, half.x, half.y}, fill, outline, Kind::Box});
}

void DebugDrawList::roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) {
    commands_.push_back(
        {{centre.x, centre.y, half.x, half.y, radius}, fill, outline, Kind::RoundedBox});
}

void DebugDrawList::triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) {
    commands_.push_back({{a.x, a.y, b.x, b.y, c.x, c.y}, fill, outline, Kind::Triangle});
}

void DebugDrawList::point(Vec2 at, float size, Colour colour) {
    commands_.push_back({{at.x, at.y, size}, colour, colour, Kind::Point});
}

void DebugDrawList::replay(DebugDraw& draw) const {
    for (const Command& c : commands_) {
        const float* v = c.values;
        switch (c.kind) {
        case Kind::Line:
            draw.line({v[0], v[1]}, {v[2], v[3]}, c.fill);
            break;
        case Kind::Box:
            draw.box({v[0], v[1]}, {v[2], v[3]}, c.fill, c.outline);
            break;
        case Kind::RoundedBox:
            draw.roundedBox({v[0], v[1]}, {v[2], v[3]}, v[4], c.fill, c.outline);
            break;
        case Kind::Triangle:
            draw.triangle({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, c.fill, c.outline);
            break;
        case Kind::Point:
            draw.point({v[0], v[1]}, v[2], c.fill);
            break;
        }
    }
}

// --- The palette's rule --------------------------------------------------------------------

namespace {

Colour scaled(Colour colour, int percent) {
    const auto channel = [percent](std::uint8_t value) {
        return std::uint8_t(std::clamp(value * percent / 100, 0, 255));
    };
    return {channel(colour.r), channel(colour.g), channel(colour.b), colour.a};
}

} // namespace

Colour DebugPalette::fillOf(BodyType type, bool asleep) const {
    const Colour colour = type == BodyType::Static      ? staticBody
                          : type == BodyType::Kinematic ? kinematicBody
                                                        : dynamicBody;
    return asleep ? scaled(colour, sleepingPercent) : colour;
}

Colour DebugPalette::outlineOf(Colour fill) const {
    return scaled(fill, outlinePercent);
}

// --- What the world draws -----------------------------------------------------------------

namespace {

constexpr float kVelocitySeconds = 0.1f;

/// The unit axis nearest to `direction` (x on a tie), as the box face it points out of.
Vec2 nearestAxis(Vec2 direction) {
    if (std::abs(direction.x) >= std::abs(direction.y))
        return {direction.x < 0.0f ? -1.0f : 1.0f, 0.0f};
    return {0.0f, direction.y < 0.0f ? -1.0f : 1.0f};
}

/// The face of the box (centre, half) that the unit axis `out` points out of, as a line.
void drawFace(DebugDraw& draw, Vec2 centre, Vec2 half, Vec2 out, Colour colour) {
    const Vec2 face = centre + Vec2{out.x * half.x, out.y * half.y};
    const Vec2 along = out.y != 0.0f ? Vec2{half.x, 0.0f} : Vec2{0.0f, half.y};
    draw.line(face - along, face + along, colour);
}

/// The corners of a ramp (or a segment: its first two) whose sloped face looks towards
/// the corner `slope` names: the sloped face's ends, then the right angle's corner.
std::array<Vec2, 3> rampCorners(Vec2 centre, Vec2 half, Vec2 slope) {
    return {centre + Vec2{slope.x * half.x, -slope.y * half.y},
            centre + Vec2{-slope.x * half.x, slope.y * half.y},
            centre + Vec2{-slope.x * half.x, -slope.y * half.y}};
}

class WorldDrawing {
public:
    WorldDrawing(const World& world, DebugDraw& draw, const DebugDrawOptions& options)
        : world_(world), draw_(draw), options_(options), palette_(options.palette),
          everything_(options.viewMin.x > options.viewMax.x ||
                      options.viewMin.y > options.viewMax.y) {
        if (everything_)
            return;
        // The bodies in view, found through the broadphase, in creation order: a large
        // level costs what its view shows. (The world's range bounds every body.)
        const auto clamped = [](Vec2 v) {
            return Vec2{std::clamp(v.x, -kMaxMagnitude, kMaxMagnitude),
                        std::clamp(v.y, -kMaxMagnitude, kMaxMagnitude)};
        };
        queryRect(world, clamped(options.viewMin), clamped(options.viewMax),
                  {.includeSensors = true}, inView_);
    }

    void grid() {
        const WorldState& state = WorldAccess::state(world_);
        const auto cell = [&](const Box& box) {
            if (inView(box))
                draw_.box((box.min + box.max) * 0.5f, (box.max - box.min) * 0.5f, {0, 0, 0, 0},
                          palette_.gridCell);
        };
        state.restingGrid.forEachCell(cell);
        state.movingGrid.forEachCell(cell);
        for (std::uint32_t i = 0; i < state.movingGrid.size(); ++i) {
            const Box& box = state.movingGrid.bounds(i);
            if (inView(box))
                draw_.box((box.min + box.max) * 0.5f, (box.max - box.min) * 0.5f, {0, 0, 0, 0},
                          palette_.gridBox);
        }
    }

    /// Every body but sensors, then sensors, so that what a sensor overlaps does not hide
    /// its outline.
    void shapes() {
        for (const bool sensors : {false, true})
            for (const BodyId body : bodies())
                if (world_.isSensor(body) == sensors)
                    shape(body);
    }

    void marks() {
        const Vec2 down = downOf(world_.gravity());
        const Vec2 right{down.y, -down.x};
        for (const BodyId body : bodies()) {
            if (world_.type(body) != BodyType::Dynamic || world_.isSensor(body))
                continue;
            const Vec2 centre = world_.position(body);
            if (options_.touching) {
                const Vec2 half = world_.halfExtents(body);
                const Touching touching = world_.touching(body);
                const std::pair<bool, Vec2> sides[] = {{touching.floor, down},
                                                       {touching.ceiling, -down},
                                                       {touching.wallLeft, -right},
                                                       {touching.wallRight, right}};
                for (const auto& [touched, side] : sides)
                    if (touched)
                        drawFace(draw_, centre, half, nearestAxis(side), palette_.touching);
            }
            if (options_.velocities && world_.isAwake(body) &&
                world_.velocity(body) != Vec2{}) // a body at rest has no arrow
                draw_.line(centre, centre + world_.velocity(body) * kVelocitySeconds,
                           palette_.velocity);
        }
    }

    /// Each touching pair once, from the body whose handle comes first: its point, and its
    /// normal drawn into the body it pushes (the dynamic one), no longer than half that
    /// body's extent along it, so that in a pile of small boxes it stays in its box.
    void contacts() {
        std::vector<ContactInfo> found;
        for (const BodyId body : bodies()) {
            world_.contacts(body, found);
            for (const ContactInfo& contact : found) {
                if (!comesFirst(body, contact.other))
                    continue;
                const bool intoBody = world_.type(body) == BodyType::Dynamic;
                const BodyId pushed = intoBody ? body : contact.other;
                const Vec2 direction = intoBody ? contact.normal : -contact.normal;
                const Vec2 half = world_.halfExtents(pushed);
                const float along = std::abs(direction.x) * half.x + std::abs(direction.y) * half.y;
                const float length = std::min(options_.markLength, along);
                draw_.point(contact.point, options_.markLength / 4.0f, palette_.contact);
                draw_.line(contact.point, contact.point + direction * length, palette_.contact);
            }
        }
    }

private:
    static bool comesFirst(BodyId a, BodyId b) {
        return a.index != b.index ? a.index < b.index : a.generation < b.generation;
    }

    bool inView(const Box& box) const {
        return everything_ || (box.min.x <= options_.viewMax.x && box.max.x >= options_.viewMin.x &&
                               box.min.y <= options_.viewMax.y && box.max.y >= options_.viewMin.y);
    }
    /// Every body, or those in view.
    std::span<const BodyId> bodies() const { return everything_ ? world_.bodies() : inView_; }

    void shape(BodyId body) {
        const BodyType type = world_.type(body);
        const bool sensor = world_.isSensor(body);
        Colour fill = palette_.fillOf(type, type != BodyType::Static && !world_.isAwake(body));
        Colour outline = world_.isBullet(body) ? palette_.bulletOutline : palette_.outlineOf(fill);
        if (sensor) {
            outline = fill;
            fill.a = 0;
        }
        const Vec2 centre = world_.position(body);
        const Vec2 half = world_.halfExtents(body);
        // The shape as the world keeps it (BodyDef::radius, slope and segment).
        const Shape& shape = WorldAccess::state(world_).shapes[body.index];
        if (shape.slope != Vec2{}) {
            const std::array<Vec2, 3> corners = rampCorners(centre, half, shape.slope);
            if (shape.segment)
                segment(corners[0], corners[1], slopeNormal(half, shape.slope),
                        sensor ? outline : fill);
            else
                draw_.triangle(corners[0], corners[1], corners[2], fill, outline);
            return;
        }
        if (shape.radius > 0.0f)
            draw_.roundedBox(centre, half, shape.radius, fill, outline);
        else
            draw_.box(centre, half, fill, outline);
        if (world_.oneWay(body) != Vec2{})
            drawFace(draw_, centre, half, nearestAxis(world_.oneWay(body)), palette_.oneWayFace);
    }

    /// A segment, with a tick from its middle towards the side it blocks: a sixth of its
    /// length, markLength at most.
    void segment(Vec2 a, Vec2 b, Vec2 normal, Colour colour) {
        draw_.line(a, b, colour);
        const Vec2 middle = (a + b) * 0.5f;
        draw_.line(middle, middle + normal * std::min(options_.markLength, length(b - a) / 6.0f),
                   colour);
    }

    const World& world_;
    DebugDraw& draw_;
    const DebugDrawOptions& options_;
    const DebugPalette& palette_;
    bool everything_;
    std::vector<BodyId> inView_;
};

} // namespace

void World::debugDraw(DebugDraw& draw, const DebugDrawOptions& options) const {
    constexpr const char* kFunction = "debugDraw";
    // Any finite size: a view may reach past the world's range, a mark be long in a view
    // of tiny bodies.
    if (!(options.markLength >= 0.0f && std::isfinite(options.markLength)))
        fail(kFunction, "options.markLength must be a finite number >= 0");
    for (const auto& [corner, name] :
         {std::pair{options.viewMin, "viewMin"}, std::pair{options.viewMax, "viewMax"}})
        if (!std::isfinite(corner.x) || !std::isfinite(corner.y))
            fail(kFunction, std::string("options.") + name + " must be finite");
    for (const auto& [percent, name] :
         {std::pair{options.palette.sleepingPercent, "sleepingPercent"},
          std::pair{options.palette.outlinePercent, "outlinePercent"}})
        if (percent < 0 || percent > 100)
            fail(kFunction, std::string("options.palette.") + name + " must be in [0, 100]");
    // The renderer may read the world, not change it (requireChangeable), while the walk
    // below holds its lists.
    const WorldState& state = WorldAccess::state(*this);
    struct Drawing {
        const WorldState& state;
        bool before = state.drawing;
        ~Drawing() { state.drawing = before; }
    } scope{state};
    state.drawing = true;
    WorldDrawing drawing(*this, draw, options);
    if (options.grid)
        drawing.grid();
    if (options.shapes)
        drawing.shapes();
    if (options.touching || options.velocities)
        drawing.marks();
    if (options.contacts)
        drawing.contacts();
}

} // namespace jostle
