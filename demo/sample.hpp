// A sample of the demo: one or more worlds side by side (panes), built afresh on reset,
// and whatever the sample does before each step (a character, a lift, a cannon).
#pragma once

#include "contact_set.hpp"
#include "world_box.hpp"

#include "jostle/scene.hpp"
#include "jostle/world.hpp"

#include <memory>
#include <string>
#include <vector>

namespace jostle::demo {

/// Text drawn above a body, e.g. a crate's mass.
struct Label {
    BodyId body;
    std::string text;
};

/// One world and the part of it the window shows.
struct Pane {
    std::unique_ptr<World> world;
    WorldBox view;
    std::string title; ///< drawn at the top of the pane, e.g. "CLASSIC"
    std::vector<Label> labels;
    /// The pairs touching now, for debug drawing; kept up to date by the main loop after
    /// every step, and empty in a new pane as its world has not stepped.
    ContactSet contacts;
};

/// The keys a sample may use to steer something, as held in this step.
struct Controls {
    bool left = false;
    bool right = false;
    bool up = false;
    bool down = false;
    /// Space or up was pressed since the last step: true for one step per press, so that
    /// a jump is taken once, however many steps a frame holds.
    bool jumpPressed = false;
};

class Sample {
public:
    virtual ~Sample() = default;

    virtual const char* name() const = 0;
    /// Builds the panes afresh: at the start, on switching to the sample, and on R.
    virtual void reset() = 0;
    /// Called before each fixed step of the panes' worlds.
    virtual void beforeStep(const Controls& /*controls*/, float /*dt*/) {}
    /// True if the sample steers a character with the letter keys A and D, which then
    /// run instead of toggling debug drawing (Tab still toggles it).
    virtual bool usesLetterKeys() const { return false; }
    /// The character the keys steer, in the first pane's world (null if there is none).
    virtual BodyId player() const { return {}; }
    /// Facts of its own for --report, printed as `name value` lines on standard output.
    virtual void report() const {}

    std::vector<Pane>& panes() { return panes_; }

protected:
    std::vector<Pane> panes_;
};

/// The box that holds every body of `world` (a 2 × 2 box around the origin if none).
WorldBox boundsOf(const World& world);

/// `box` made taller by `fraction` of its height, upward: room above a scene to drop
/// boxes into with the mouse.
WorldBox withHeadroom(WorldBox box, float fraction);

/// A pane holding a new, empty world made from `def`: the sample fills it, and sets its
/// view.
Pane paneWithWorld(const WorldDef& def);

/// A pane holding a new world made from `scene`, showing all its bodies.
Pane paneFromScene(const Scene& scene, std::string title, float headroom);

/// How a pane's world is drawn (World::debugDraw), in the window and on the web page: with
/// `debug`, its contacts, velocities, sides touched and broadphase cells too, and sleeping
/// bodies dimmed; marks `markLength` long at most; what touches `view` only.
DebugDrawOptions paneDrawOptions(bool debug, float markLength, WorldBox view);

} // namespace jostle::demo
