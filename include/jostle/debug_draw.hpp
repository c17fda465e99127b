// Debug drawing: what the engine sees, drawn by the game's own renderer over its sprites
// in one call (docs/debug-draw.md).
//
//     struct Lines : jostle::DebugDraw {
//         void line(jostle::Vec2 from, jostle::Vec2 to, jostle::Colour colour) override {
//             myRenderer.line(from.x, from.y, to.x, to.y, colour.r, colour.g, colour.b);
//         }
//     };
//     Lines lines;
//     world.debugDraw(lines);                               // every shape, outlined
//     world.debugDraw(lines, {.contacts = true, .grid = true});
//
// `line` is the one call a renderer must draw; the others are drawn with lines unless the
// renderer overrides them to fill. Every length and point is in world units: the game's
// camera maps them to its screen as it maps its sprites.
#pragma once

#include "jostle/body.hpp"
#include "jostle/math.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace jostle {

/// A colour: red, green, blue and opacity, 0 to 255 each (sRGB).
struct Colour {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;
    friend constexpr bool operator==(Colour, Colour) = default;
};

/// The colours debugDraw uses. A body's fill is its type's colour (dimmed while it
/// sleeps); its outline is the fill darkened, so that boxes side by side stay apart.
struct DebugPalette {
    Colour staticBody{150, 150, 150};
    Colour kinematicBody{70, 130, 230};
    Colour dynamicBody{240, 150, 60};
    int sleepingPercent = 55; ///< a sleeping body's fill: its type's colour scaled so
    int outlinePercent = 60;  ///< an outline: its fill scaled so
    Colour bulletOutline{255, 255, 255};
    Colour oneWayFace{230, 230, 230}; ///< the face a one-way body blocks from
    Colour contact{250, 250, 120};    ///< contact points and normals
    Colour velocity{90, 220, 120};
    Colour touching{230, 60, 60};  ///< the sides a dynamic body touched
    Colour gridCell{50, 110, 140}; ///< the broadphase's cells that hold boxes
    Colour gridBox{110, 220, 250}; ///< the moving bodies' boxes as the broadphase has them

    /// A body's fill: its type's colour, scaled by sleepingPercent (rounded down) while it
    /// sleeps. A sensor is drawn with this as its outline and a fill of opacity 0.
    Colour fillOf(BodyType type, bool asleep) const;
    /// The outline of a body filled with `fill`: scaled by outlinePercent (rounded down).
    Colour outlineOf(Colour fill) const;
};

/// What debugDraw draws. Bodies are drawn in their shapes: sensors outlined only and
/// last; a one-way body's blocking face and a segment's blocking side marked. Marks with
/// no length of their own (a normal, a segment's tick, a point's cross) are `markLength`
/// long at most: a game drawing in pixels sets it to a few pixels in world units.
struct DebugDrawOptions {
    bool shapes = true;      ///< every body, tile maps' merged boxes among them
    bool contacts = false;   ///< every touching pair: where it touches, and its normal
    bool velocities = false; ///< awake dynamic bodies: a tenth of a second of their motion
    bool touching = false;   ///< the sides each dynamic body touched in the last step
    bool grid = false;       ///< the broadphase's occupied cells and its moving boxes
    float markLength = 0.25f;
    /// Only what touches this box is drawn (a game's view); a box with min > max on
    /// either axis (the default) draws everything.
    Vec2 viewMin{1.0f, 1.0f};
    Vec2 viewMax{0.0f, 0.0f};
    DebugPalette palette{};
};

/// A game's renderer, as debugDraw calls it. Points are in world units. A fill whose
/// opacity is 0 is not filled: only the outline is drawn. Its functions may read the world
/// but not change it: a change throws jostle::Error ("createBody: called from a DebugDraw
/// function ...").
class DebugDraw {
public:
    virtual ~DebugDraw() = default;
    /// A straight line.
    virtual void line(Vec2 from, Vec2 to, Colour colour) = 0;
    /// An axis-aligned box by its centre and half extents. Default: its outline in lines.
    virtual void box(Vec2 centre, Vec2 half, Colour fill, Colour outline);
    /// A box whose corners are rounded by `radius` (<= both half extents): a circle when
    /// both half extents are the radius, a capsule when one is. Default: its outline in
    /// lines, 6 to a corner.
    virtual void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline);
    /// A triangle (a ramp), its corners in order around it. Default: its outline in lines.
    virtual void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline);
    /// A point (a contact). Default: a cross of lines `size` wide.
    virtual void point(Vec2 at, float size, Colour colour);
};

/// A DebugDraw that keeps the calls, to draw them later (on a render thread, after the
/// step) or to walk them (how the Lua and JavaScript bindings draw).
///
///     jostle::DebugDrawList list;
///     world.debugDraw(list);    // during the update
///     list.replay(myRenderer);  // when drawing
class DebugDrawList final : public DebugDraw {
public:
    enum class Kind : std::uint32_t { Line, Box, RoundedBox, Triangle, Point };
    /// One call. `values`: a line's ends (x1, y1, x2, y2); a box's centre and half extents
    /// (x, y, hw, hh), a rounded box's then its radius; a triangle's corners (x1, y1, x2,
    /// y2, x3, y3); a point's place and size (x, y, size). A line's and a point's colour is
    /// `fill`.
    struct Command {
        float values[6];
        Colour fill;
        Colour outline;
        Kind kind;
    };

    void line(Vec2 from, Vec2 to, Colour colour) override;
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override;
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override;
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override;
    void point(Vec2 at, float size, Colour colour) override;

    /// The calls kept, in order, since the last clear().
    std::span<const Command> commands() const { return commands_; }
    /// Forgets the calls, keeping the memory for the next frame's.
    void clear() { commands_.clear(); }
    /// Makes the calls again on `draw`, in order.
    void replay(DebugDraw& draw) const;

private:
    std::vector<Command> commands_;
};

} // namespace jostle
