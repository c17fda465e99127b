// The main loop: see app.hpp; the keys are listed in docs/demo.md.
#include "app.hpp"

#include "draw_pane.hpp"
#include "font.hpp"
#include "grid_picture.hpp"
#include "input_script.hpp"
#include "mouse_drag.hpp"
#include "palette.hpp"
#include "sample_list.hpp"
#include "screenshot.hpp"

#include "jostle/fixed_step.hpp"

#include <SDL.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace jostle::demo {

namespace {

constexpr int kWindowWidth = 1280;
constexpr int kWindowHeight = 720;
constexpr int kTextScale = 2;
constexpr int kLineHeight = 20;
/// Room for the sample list and the statistics above the panes, and the help below.
constexpr int kHeaderHeight = 2 * kLineHeight + 8;
constexpr int kFooterHeight = kLineHeight + 4;
constexpr int kPaneGap = 4;
constexpr float kStepHz = 60.0f;
/// Slow motion plays the world at this fraction of real time.
constexpr float kSlowMotion = 0.25f;
/// A frame longer than this (a breakpoint, a dragged window) counts as this long.
constexpr float kLongestFrame = 0.25f;
/// Right-click boxes: this many pixels wide on screen, whatever the pane's scale.
constexpr float kSpawnHalfPixels = 10.0f;
/// The step time shown is smoothed over about this many frames, so it can be read.
constexpr double kStatsSmoothing = 1.0 / 20.0;

struct State {
    std::vector<std::unique_ptr<Sample>> samples;
    std::size_t current = 0;
    bool running = true;
    bool paused = false;
    bool stepOnce = false;
    bool slow = false;
    bool debug = false;
    bool jumpQueued = false;
    /// The keys held down, from the key events rather than SDL_GetKeyboardState, so that
    /// keys played by --input (pushed events, which SDL's keyboard state does not see)
    /// steer as real ones do.
    std::array<bool, SDL_NUM_SCANCODES> held{};
    MouseDrag drag;
    double stepMs = 0.0;
    /// Whether the header shows the step time: not in a counted run (--frames), whose
    /// frames, screenshots included, are then the same every time.
    bool showStepTime = true;
    /// Steps of the current sample, since it was (re)started, after which a kinematic
    /// body overlapped a static one: a lift whose shaft a level's walls cross (--report).
    std::size_t kinematicInStaticSteps = 0;
};

Sample& sample(State& state) {
    return *state.samples[state.current];
}

/// The panes side by side across the window, under the header.
std::vector<View> layout(Sample& current) {
    std::vector<View> views;
    const auto& panes = current.panes();
    const int count = static_cast<int>(panes.size());
    const int width = (kWindowWidth - kPaneGap * (count + 1)) / count;
    const int height = kWindowHeight - kHeaderHeight - kFooterHeight;
    for (int i = 0; i < count; ++i) {
        const SDL_Rect screen{kPaneGap + i * (width + kPaneGap), kHeaderHeight, width, height};
        views.push_back(View::fit(panes[static_cast<std::size_t>(i)].view, screen));
    }
    return views;
}

void select(State& state, std::size_t index, SDL_Window* window) {
    state.drag.release();
    state.kinematicInStaticSteps = 0;
    state.current = index;
    sample(state).reset();
    const std::string title =
        "jostle-demo: " + std::to_string(index + 1) + " " + sample(state).name();
    SDL_SetWindowTitle(window, title.c_str());
}

void onKey(State& state, SDL_Keycode key, SDL_Window* window) {
    if (key >= SDLK_1 && key < SDLK_1 + static_cast<int>(state.samples.size())) {
        select(state, static_cast<std::size_t>(key - SDLK_1), window);
        return;
    }
    switch (key) {
    case SDLK_ESCAPE:
        state.running = false;
        break;
    case SDLK_p:
        state.paused = !state.paused;
        break;
    case SDLK_n:
        state.paused = true;
        state.stepOnce = true;
        break;
    case SDLK_s:
        state.slow = !state.slow;
        break;
    case SDLK_TAB:
        state.debug = !state.debug;
        break;
    case SDLK_d:
        // D runs right in the samples with a character; Tab toggles debug everywhere, and
        // D is an alias only where it steers nothing.
        if (!sample(state).usesLetterKeys())
            state.debug = !state.debug;
        break;
    case SDLK_r:
        select(state, state.current, window);
        break;
    case SDLK_SPACE:
    case SDLK_UP:
    case SDLK_w:
        state.jumpQueued = true;
        break;
    default:
        break;
    }
}

void onMouseButton(State& state, const SDL_MouseButtonEvent& event) {
    const std::vector<View> views = layout(sample(state));
    for (std::size_t i = 0; i < views.size(); ++i) {
        if (!views[i].contains(event.x, event.y))
            continue;
        Pane& pane = sample(state).panes()[i];
        const Vec2 point = views[i].toWorld(event.x, event.y);
        if (event.button == SDL_BUTTON_LEFT) {
            state.drag.grab(pane, point);
        } else if (event.button == SDL_BUTTON_RIGHT) {
            const float half = kSpawnHalfPixels / views[i].scale();
            pane.world->createBody(
                {.x = point.x, .y = point.y, .hw = half, .hh = half, .bounce = 0.2f});
        }
    }
}

void handleEvents(State& state, SDL_Window* window) {
    SDL_Event event;
    while (SDL_PollEvent(&event)) {
        switch (event.type) {
        case SDL_QUIT:
            state.running = false;
            break;
        case SDL_KEYDOWN:
            if (event.key.keysym.scancode < SDL_NUM_SCANCODES)
                state.held[event.key.keysym.scancode] = true;
            if (event.key.repeat == 0)
                onKey(state, event.key.keysym.sym, window);
            break;
        case SDL_KEYUP:
            if (event.key.keysym.scancode < SDL_NUM_SCANCODES)
                state.held[event.key.keysym.scancode] = false;
            break;
        case SDL_MOUSEBUTTONDOWN:
            onMouseButton(state, event.button);
            break;
        case SDL_MOUSEBUTTONUP:
            if (event.button.button == SDL_BUTTON_LEFT)
                state.drag.release();
            break;
        case SDL_MOUSEMOTION:
            for (const View& view : layout(sample(state)))
                if (view.contains(event.motion.x, event.motion.y))
                    state.drag.moveTo(view.toWorld(event.motion.x, event.motion.y));
            break;
        default:
            break;
        }
    }
}

Controls readControls(State& state) {
    const auto& keys = state.held;
    const bool letters = sample(state).usesLetterKeys();
    Controls controls;
    controls.left = keys[SDL_SCANCODE_LEFT] || (letters && keys[SDL_SCANCODE_A]);
    controls.right = keys[SDL_SCANCODE_RIGHT] || (letters && keys[SDL_SCANCODE_D]);
    controls.up = keys[SDL_SCANCODE_UP];
    controls.down = keys[SDL_SCANCODE_DOWN];
    controls.jumpPressed = state.jumpQueued;
    state.jumpQueued = false;
    return controls;
}

/// Whether a kinematic body of `world` overlaps a static one by more than touching.
/// Kinematic bodies pass through static ones, so only a look tells that a lift's path is
/// blocked.
bool kinematicInStatic(const World& world) {
    for (const BodyId mover : world.bodies()) {
        if (world.type(mover) != BodyType::Kinematic)
            continue;
        const Vec2 at = world.position(mover);
        const Vec2 half = world.halfExtents(mover);
        for (const BodyId solid : world.bodies()) {
            if (world.type(solid) != BodyType::Static)
                continue;
            const Vec2 apart = world.position(solid) - at;
            const Vec2 reach = world.halfExtents(solid) + half;
            if (std::abs(apart.x) < reach.x && std::abs(apart.y) < reach.y)
                return true;
        }
    }
    return false;
}

void stepWorlds(State& state, int steps, float dt) {
    for (int i = 0; i < steps; ++i) {
        const Controls controls = readControls(state);
        sample(state).beforeStep(controls, dt);
        state.drag.pull(dt);
        const Uint64 start = SDL_GetPerformanceCounter();
        for (Pane& pane : sample(state).panes())
            pane.world->step(dt);
        const Uint64 end = SDL_GetPerformanceCounter();
        // Every step, debug drawing on or off: the events of a step are gone after the
        // next, and turning debug on must show what touches now.
        bool overlap = false;
        for (Pane& pane : sample(state).panes()) {
            pane.contacts.update(*pane.world);
            overlap = overlap || kinematicInStatic(*pane.world);
        }
        state.kinematicInStaticSteps += overlap ? 1 : 0;
        const double ms = 1000.0 * static_cast<double>(end - start) /
                          static_cast<double>(SDL_GetPerformanceFrequency());
        state.stepMs += (ms - state.stepMs) * kStatsSmoothing;
    }
}

/// The keys, as they work in `current`: Tab is the debug key everywhere; D is one too
/// only where it does not run.
std::string helpLine(Sample& current) {
    const std::string common = "p pause  n step  s slow  r reset  esc quit  ";
    if (current.usesLetterKeys())
        return "<- -> a d run  space jump  tab debug  " + common + "drag move  r-click box";
    return "tab or d debug  " + common + "left-drag move  right-click box";
}

void drawHeader(SDL_Renderer* renderer, State& state) {
    int x = 8;
    for (std::size_t i = 0; i < state.samples.size(); ++i) {
        setColour(renderer, i == state.current ? kTextHighlight : kTextDim);
        x = drawText(renderer, x, 6, kTextScale,
                     std::to_string(i + 1) + " " + state.samples[i]->name() + "  ");
    }
    std::size_t bodies = 0;
    std::string models;
    for (const Pane& pane : sample(state).panes()) {
        bodies += pane.world->bodyCount();
        models += (models.empty() ? "" : " | ") + std::string(toString(pane.world->solver()));
    }
    std::string stats = "bodies " + std::to_string(bodies) + "   ";
    if (state.showStepTime) {
        char stepText[32];
        std::snprintf(stepText, sizeof stepText, "%.2f", state.stepMs);
        stats += "step " + std::string(stepText) + " ms   ";
    }
    stats += "model " + models + "   60 hz";
    if (state.paused)
        stats += "   paused";
    if (state.slow)
        stats += "   slow";
    if (state.debug)
        stats += "   debug";
    setColour(renderer, kText);
    drawText(renderer, 8, 6 + kLineHeight, kTextScale, stats);
    setColour(renderer, kTextDim);
    drawText(renderer, 8, kWindowHeight - kLineHeight, kTextScale, helpLine(sample(state)));
}

void drawFrame(SDL_Renderer* renderer, State& state) {
    setColour(renderer, scaled(kBackground, 70));
    SDL_RenderClear(renderer);
    const std::vector<View> views = layout(sample(state));
    for (std::size_t i = 0; i < views.size(); ++i)
        drawPane(renderer, sample(state).panes()[i], views[i], state.debug, 1.0f / kStepHz);
    drawHeader(renderer, state);
}

/// --report: facts a test can check, one `name value` per line.
void printReport(State& state) {
    Sample& current = sample(state);
    std::size_t bodies = 0;
    for (const Pane& pane : current.panes())
        bodies += pane.world->bodyCount();
    std::printf("sample %s\n", current.name());
    std::printf("sample_number %zu\n", state.current + 1);
    std::printf("bodies %zu\n", bodies);
    std::printf("paused %d\n", state.paused ? 1 : 0);
    std::printf("slow %d\n", state.slow ? 1 : 0);
    std::printf("debug %d\n", state.debug ? 1 : 0);
    // What debug drawing shows (drawn or not): the touching pairs of all panes, and the
    // broadphase picture of the first.
    std::size_t contacts = 0;
    for (const Pane& pane : current.panes())
        contacts += pane.contacts.count(*pane.world);
    std::printf("contacts %zu\n", contacts);
    std::printf("kinematic_in_static %zu\n", state.kinematicInStaticSteps);
    const GridPicture grid = pictureGrid(*current.panes().front().world, 1.0f / kStepHz);
    std::printf("grid %s\ngrid_boxes %zu\n", grid.boxes.empty() ? "none" : grid.name.c_str(),
                grid.boxes.size());
    if (!grid.boxes.empty())
        std::printf("grid_cell %.3f\ngrid_level %d\ngrid_level_boxes %zu\n",
                    grid.cellSize(grid.mainLevel), grid.mainLevel, grid.inMainLevel);
    const World& world = *current.panes().front().world;
    if (const BodyId player = current.player(); world.isValid(player)) {
        const Vec2 position = world.position(player);
        const Vec2 velocity = world.velocity(player);
        std::printf("player_x %.3f\nplayer_y %.3f\n", static_cast<double>(position.x),
                    static_cast<double>(position.y));
        std::printf("player_vx %.3f\nplayer_vy %.3f\n", static_cast<double>(velocity.x),
                    static_cast<double>(velocity.y));
        std::printf("player_floor %d\n", world.touching(player).floor ? 1 : 0);
    }
    current.report();
    std::printf("dragging %d\n", state.drag.holding() ? 1 : 0);
    if (state.drag.holding()) {
        const Vec2 held = state.drag.heldPosition();
        std::printf("dragged_x %.3f\ndragged_y %.3f\n", static_cast<double>(held.x),
                    static_cast<double>(held.y));
    }
    std::fflush(stdout);
}

} // namespace

int probeDisplay() {
    if (SDL_Init(SDL_INIT_VIDEO) != 0)
        return 1;
    // Without a display SDL falls back to drivers that draw nowhere: no one would see.
    const std::string driver = SDL_GetCurrentVideoDriver();
    if (driver == "offscreen" || driver == "dummy") {
        SDL_Quit();
        return 1;
    }
    SDL_Window* window = SDL_CreateWindow("jostle-demo", SDL_WINDOWPOS_UNDEFINED,
                                          SDL_WINDOWPOS_UNDEFINED, 64, 64, SDL_WINDOW_HIDDEN);
    const int status = window != nullptr ? 0 : 1;
    if (window != nullptr)
        SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

int runApp(const Options& options) {
    // Read before SDL starts, so that a mistake in it costs no window.
    InputPlayer input(options.input.empty() ? std::vector<ScriptEvent>{}
                                            : loadInputScript(options.input));
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "jostle-demo: cannot start SDL: %s\n", SDL_GetError());
        return 1;
    }
    SDL_Window* window = SDL_CreateWindow("jostle-demo", SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, kWindowWidth, kWindowHeight, 0);
    // A counted run goes as fast as it can; an interactive one waits for the screen.
    const Uint32 flags = options.frames > 0 ? 0u : Uint32{SDL_RENDERER_PRESENTVSYNC};
    SDL_Renderer* renderer = window != nullptr ? SDL_CreateRenderer(window, -1, flags) : nullptr;
    if (renderer == nullptr) {
        std::fprintf(stderr, "jostle-demo: cannot open a window: %s\n", SDL_GetError());
        if (window != nullptr)
            SDL_DestroyWindow(window);
        SDL_Quit();
        return 1;
    }

    State state;
    state.samples = makeSamples();
    state.showStepTime = options.frames == 0;
    select(state, static_cast<std::size_t>(options.sample - 1), window);
    FixedStep clock(1.0f / kStepHz);
    Uint64 last = SDL_GetPerformanceCounter();
    int status = 0;
    for (int frame = 1; state.running; ++frame) {
        input.pushFrame(frame, window);
        handleEvents(state, window);
        const Uint64 now = SDL_GetPerformanceCounter();
        float seconds =
            static_cast<float>(now - last) / static_cast<float>(SDL_GetPerformanceFrequency());
        last = now;
        if (options.frames > 0)
            seconds = 1.0f / kStepHz;
        seconds = std::min(seconds, kLongestFrame) * (state.slow ? kSlowMotion : 1.0f);
        int steps = clock.advance(seconds);
        if (state.paused)
            steps = state.stepOnce ? 1 : 0;
        state.stepOnce = false;
        stepWorlds(state, steps, clock.dt());

        drawFrame(renderer, state);
        const bool lastFrame = options.frames > 0 && frame >= options.frames;
        if (lastFrame && !options.screenshot.empty()) {
            const std::string error =
                saveScreenshot(renderer, kWindowWidth, kWindowHeight, options.screenshot);
            if (!error.empty()) {
                std::fprintf(stderr, "jostle-demo: cannot save %s: %s\n",
                             options.screenshot.c_str(), error.c_str());
                status = 1;
            }
        }
        SDL_RenderPresent(renderer);
        if (lastFrame)
            state.running = false;
    }
    // Printed on Esc or closing the window too, when asked for.
    if (options.report)
        printReport(state);
    SDL_DestroyRenderer(renderer);
    SDL_DestroyWindow(window);
    SDL_Quit();
    return status;
}

} // namespace jostle::demo
