// The page's side of the module: the demo's samples (demo/sample_*.cpp) behind a C
// surface that bindings/web/page/page_module.js wraps. One page, one set of samples: the
// state is a single Page. What is read back (bodies, labels, drawing) is written into one
// float buffer and read from the module's memory: a frame costs a few calls per pane,
// not a call per body.
#include "grid_picture.hpp"
#include "mouse_drag.hpp"
#include "sample_check.hpp"
#include "sample_list.hpp"

#include "shared/drawn_shape.hpp"

#include <emscripten/emscripten.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace jostle::web {

namespace {

/// The keys of jostle_page_step, one bit each.
enum Key : int { kLeft = 1, kRight = 2, kUp = 4, kDown = 8, kJump = 16 };

/// A body as the page reads it: 12 floats (see jostle_page_read_bodies).
constexpr std::size_t kBodyFloats = 12;

/// A scene file loaded by the page: one pane in the model the file names.
class SceneSample : public demo::Sample {
public:
    explicit SceneSample(Scene scene) : scene_(std::move(scene)) {}
    const char* name() const override { return "scene"; }
    void reset() override {
        panes_.clear();
        panes_.push_back(demo::paneFromScene(scene_, toString(scene_.world.solver), 0.2f));
    }

private:
    Scene scene_;
};

struct Page {
    std::vector<std::unique_ptr<demo::Sample>> samples = demo::makeSamples();
    std::unique_ptr<demo::Sample> scene; ///< a scene file, when one is loaded
    demo::Sample* current = nullptr;
    demo::MouseDrag drag;
    std::vector<float> out; ///< what the last read wrote
    DebugDrawList drawn;    ///< what the last jostle_page_debug_draw drew
    std::string text;       ///< what the last call that returns text returned
};

Page& page() {
    static Page instance;
    return instance;
}

void start(demo::Sample& sample);

/// The sample shown; the first, started, if none was chosen yet.
demo::Sample& current() {
    Page& p = page();
    if (p.current == nullptr)
        start(*p.samples.front());
    return *p.current;
}

/// The pane `index` of the current sample, or null if there is none such.
demo::Pane* paneAt(int index) {
    auto& panes = current().panes();
    if (index < 0 || static_cast<std::size_t>(index) >= panes.size())
        return nullptr;
    return &panes[static_cast<std::size_t>(index)];
}

void start(demo::Sample& sample) {
    Page& p = page();
    p.drag.release();
    p.current = &sample;
    sample.reset();
}

int flagsOf(const World& world, BodyId body) {
    const Touching touching = world.touching(body);
    return (world.isAwake(body) ? 1 : 0) | (world.isBullet(body) ? 2 : 0) |
           (world.isSensor(body) ? 4 : 0) | (touching.floor ? 8 : 0) | (touching.ceiling ? 16 : 0) |
           (touching.wallLeft ? 32 : 0) | (touching.wallRight ? 64 : 0);
}

const char* keep(std::string text) {
    page().text = std::move(text);
    return page().text.c_str();
}

} // namespace

} // namespace jostle::web

using namespace jostle;
using namespace jostle::web;

extern "C" {

EMSCRIPTEN_KEEPALIVE int jostle_page_sample_count() {
    return static_cast<int>(page().samples.size());
}

EMSCRIPTEN_KEEPALIVE const char* jostle_page_sample_name(int index) {
    if (index < 0 || index >= jostle_page_sample_count())
        return "";
    return page().samples[static_cast<std::size_t>(index)]->name();
}

/// Starts sample `index` (from 0) afresh; false if there is no such sample.
EMSCRIPTEN_KEEPALIVE bool jostle_page_select(int index) {
    if (index < 0 || index >= jostle_page_sample_count())
        return false;
    start(*page().samples[static_cast<std::size_t>(index)]);
    return true;
}

/// Starts the current sample again (R).
EMSCRIPTEN_KEEPALIVE void jostle_page_reset() {
    start(current());
}

/// Loads a scene file's text as the current sample. Returns "" or the loader's error,
/// which names the place (`bodies[3].hw: must be > 0`); on an error nothing changes.
EMSCRIPTEN_KEEPALIVE const char* jostle_page_load_scene(const char* json) {
    try {
        auto sample = std::make_unique<SceneSample>(parseScene(json));
        sample->reset();
        page().scene = std::move(sample);
        start(*page().scene);
        return keep("");
    } catch (const std::exception& error) {
        return keep(error.what());
    }
}

EMSCRIPTEN_KEEPALIVE const char* jostle_page_current_name() {
    return current().name();
}

/// True if the sample steers a character with A and D (which then do not toggle debug).
EMSCRIPTEN_KEEPALIVE bool jostle_page_uses_letter_keys() {
    return current().usesLetterKeys();
}

/// One fixed step of every pane: the sample's own work with the keys held (`keys`, the
/// bits of Key), the mouse's pull, the worlds' steps and the touching pairs kept for
/// debug drawing. Returns the milliseconds the worlds' steps took, nothing else.
EMSCRIPTEN_KEEPALIVE double jostle_page_step(int keys, float dt) {
    demo::Sample& sample = current();
    demo::Controls controls;
    controls.left = (keys & kLeft) != 0;
    controls.right = (keys & kRight) != 0;
    controls.up = (keys & kUp) != 0;
    controls.down = (keys & kDown) != 0;
    controls.jumpPressed = (keys & kJump) != 0;
    sample.beforeStep(controls, dt);
    page().drag.pull(dt);
    const double start = emscripten_get_now();
    for (demo::Pane& pane : sample.panes())
        pane.world->step(dt);
    const double end = emscripten_get_now();
    for (demo::Pane& pane : sample.panes())
        pane.contacts.update(*pane.world);
    return end - start;
}

EMSCRIPTEN_KEEPALIVE int jostle_page_pane_count() {
    return static_cast<int>(current().panes().size());
}

EMSCRIPTEN_KEEPALIVE const char* jostle_page_pane_title(int index) {
    const demo::Pane* pane = paneAt(index);
    return pane != nullptr ? pane->title.c_str() : "";
}

/// The model of the pane's world: "classic" or "physical".
EMSCRIPTEN_KEEPALIVE const char* jostle_page_pane_model(int index) {
    const demo::Pane* pane = paneAt(index);
    return pane != nullptr ? toString(pane->world->solver()) : "";
}

EMSCRIPTEN_KEEPALIVE int jostle_page_body_count(int index) {
    const demo::Pane* pane = paneAt(index);
    return pane != nullptr ? static_cast<int>(pane->world->bodyCount()) : 0;
}

/// The float buffer the last read wrote.
EMSCRIPTEN_KEEPALIVE const float* jostle_page_data() {
    return page().out.data();
}

/// The box of the world the pane shows: min x, min y, max x, max y. Returns 4.
EMSCRIPTEN_KEEPALIVE int jostle_page_read_view(int index) {
    const demo::Pane* pane = paneAt(index);
    if (pane == nullptr)
        return 0;
    page().out = {pane->view.min.x, pane->view.min.y, pane->view.max.x, pane->view.max.y};
    return 4;
}

/// Every body of the pane in creation order, 12 floats each: centre x, y; half extents
/// hw, hh; velocity x, y; type (0 static, 1 kinematic, 2 dynamic); flags (1 awake,
/// 2 bullet, 4 sensor, touched last step: 8 floor, 16 ceiling, 32 left wall, 64 right
/// wall); shape (0 box, 1 rounded, 2 ramp, 3 segment); corner radius; a direction x, y
/// (a ramp's or segment's slope corner, a box's one-way normal). Returns the count.
EMSCRIPTEN_KEEPALIVE int jostle_page_read_bodies(int index) {
    const demo::Pane* pane = paneAt(index);
    if (pane == nullptr)
        return 0;
    const World& world = *pane->world;
    std::vector<float>& out = page().out;
    out.clear();
    out.reserve(world.bodyCount() * kBodyFloats);
    for (const BodyId body : world.bodies()) {
        const shared::DrawnShape shape = shared::DrawnShape::of(world, body);
        const Vec2 direction =
            shape.kind == shared::DrawnKind::Ramp || shape.kind == shared::DrawnKind::Segment
                ? shape.slope
                : world.oneWay(body);
        const Vec2 velocity = world.velocity(body);
        out.insert(out.end(),
                   {shape.centre.x, shape.centre.y, shape.half.x, shape.half.y, velocity.x,
                    velocity.y, static_cast<float>(world.type(body)),
                    static_cast<float>(flagsOf(world, body)), static_cast<float>(shape.kind),
                    shape.radius, direction.x, direction.y});
    }
    return static_cast<int>(world.bodyCount());
}

/// The pane's world drawn as the SDL demo draws it (World::debugDraw): with `debug`, the
/// contacts, velocities, touched sides and the broadphase's cells too, and sleeping bodies
/// dimmed; marks `markLength` long at most; only what touches the box (minX, minY) to
/// (maxX, maxY). Returns the number of calls, jostle_page_draw_calls their address.
EMSCRIPTEN_KEEPALIVE int jostle_page_debug_draw(int index, bool debug, float markLength, float minX,
                                                float minY, float maxX, float maxY) {
    const demo::Pane* pane = paneAt(index);
    DebugDrawList& list = page().drawn;
    list.clear();
    if (pane == nullptr)
        return 0;
    const DebugDrawOptions options =
        demo::paneDrawOptions(debug, markLength, {{minX, minY}, {maxX, maxY}});
    try {
        pane->world->debugDraw(list, options);
    } catch (const Error&) {
        list.clear(); // a view no canvas shows (a pane of no size): nothing to draw
    }
    return static_cast<int>(list.commands().size());
}

/// The calls the last jostle_page_debug_draw kept (jostle::DebugDrawList::Command each).
EMSCRIPTEN_KEEPALIVE const DebugDrawList::Command* jostle_page_draw_calls() {
    return page().drawn.commands().data();
}

/// The picture of the pane's broadphase grid (demo/grid_picture.hpp), for steps of `dt`:
/// 3 floats, its main level, level 0's cell size and the boxes in the main level; then
/// 7 floats a box, its grid box min x, y, max x, y, its growth x, y and its level.
/// Returns the number of boxes; the grid's name by jostle_page_grid_name.
EMSCRIPTEN_KEEPALIVE int jostle_page_read_grid(int index, float dt) {
    const demo::Pane* pane = paneAt(index);
    if (pane == nullptr)
        return 0;
    const demo::GridPicture grid = demo::pictureGrid(*pane->world, dt);
    std::vector<float>& out = page().out;
    out = {static_cast<float>(grid.mainLevel), static_cast<float>(grid.levelZero),
           static_cast<float>(grid.inMainLevel)};
    for (const demo::GridBox& box : grid.boxes)
        out.insert(out.end(),
                   {box.bounds.min.x, box.bounds.min.y, box.bounds.max.x, box.bounds.max.y,
                    box.growth.x, box.growth.y, static_cast<float>(box.level)});
    page().text = grid.name;
    return static_cast<int>(grid.boxes.size());
}

/// The name of the grid the last jostle_page_read_grid pictured ("moving", "resting",
/// "dynamic", "static").
EMSCRIPTEN_KEEPALIVE const char* jostle_page_grid_name() {
    return page().text.c_str();
}

/// The labels of the pane whose bodies exist, 4 floats each: the body's centre x, y and
/// half extents; their texts by jostle_page_label_text in the same order.
EMSCRIPTEN_KEEPALIVE int jostle_page_read_labels(int index) {
    const demo::Pane* pane = paneAt(index);
    if (pane == nullptr)
        return 0;
    std::vector<float>& out = page().out;
    out.clear();
    for (const demo::Label& label : pane->labels) {
        if (!pane->world->isValid(label.body))
            continue;
        const Vec2 at = pane->world->position(label.body);
        const Vec2 half = pane->world->halfExtents(label.body);
        out.insert(out.end(), {at.x, at.y, half.x, half.y});
    }
    return static_cast<int>(out.size() / 4);
}

EMSCRIPTEN_KEEPALIVE const char* jostle_page_label_text(int index, int label) {
    const demo::Pane* pane = paneAt(index);
    if (pane == nullptr)
        return "";
    int seen = 0;
    for (const demo::Label& each : pane->labels)
        if (pane->world->isValid(each.body) && seen++ == label)
            return each.text.c_str();
    return "";
}

/// The character the keys steer, in the first pane: x, y, vx, vy, and 1 if it touched a
/// floor in the last step. Returns 5, or 0 if the sample has none.
EMSCRIPTEN_KEEPALIVE int jostle_page_read_player() {
    demo::Sample& sample = current();
    const BodyId player = sample.player();
    const World& world = *sample.panes().front().world;
    if (!world.isValid(player))
        return 0;
    const Vec2 at = world.position(player);
    const Vec2 velocity = world.velocity(player);
    page().out = {at.x, at.y, velocity.x, velocity.y, world.touching(player).floor ? 1.0f : 0.0f};
    return 5;
}

/// Left button: grabs the dynamic body at (x, y) of pane `index`, in world units.
/// Returns true if there was one.
EMSCRIPTEN_KEEPALIVE bool jostle_page_grab(int index, float x, float y) {
    if (demo::Pane* pane = paneAt(index))
        page().drag.grab(*pane, {x, y});
    return page().drag.holding();
}

EMSCRIPTEN_KEEPALIVE void jostle_page_drag_to(float x, float y) {
    page().drag.moveTo({x, y});
}

EMSCRIPTEN_KEEPALIVE void jostle_page_release() {
    page().drag.release();
}

/// Right button: drops a box of half width `half` at (x, y) of pane `index`.
EMSCRIPTEN_KEEPALIVE void jostle_page_drop_box(int index, float x, float y, float half) {
    if (demo::Pane* pane = paneAt(index))
        pane->world->createBody({.x = x, .y = y, .hw = half, .hh = half, .bounce = 0.2f});
}

/// The check of sample `index` (sample_check.hpp), on a fresh copy of the samples, in
/// decimal; the page's current sample is left alone.
EMSCRIPTEN_KEEPALIVE const char* jostle_page_check(int index) {
    auto samples = demo::makeSamples();
    if (index < 0 || static_cast<std::size_t>(index) >= samples.size())
        return "";
    return keep(
        std::to_string(runSampleCheck(*samples[static_cast<std::size_t>(index)], kCheckSteps)));
}

} // extern "C"
