// jostle-soak: a busy world for an hour of simulated time (216,000 steps of 1/60 s), to
// see that memory stays flat and that the invariants hold over a long run.
//
//     jostle-soak [--minutes N] [--seed S]
//
// A level of tiles (a floor, walls, platforms) with kinematic lifts, and a few thousand
// crates: a steady rain of them, each destroyed when its time is up or when it falls out
// of the level, so bodies are created and destroyed all the time. Piles fall asleep and
// are woken (kicked, woken by hand, or left without the tiles they stood on); platform
// tiles are dug and rebuilt (never into a crate), holes opened in the floor and closed
// (once no crate is in the way); rays, boxes and a character (moveAndSlide) query the
// world every step.
//
// Checked every step: every state finite, every live handle valid and every destroyed
// one stale, bodyCount what was created minus what was destroyed (tests/fuzz/
// invariants.hpp). Checked for each crate when it comes to rest (it falls asleep, or has
// been at rest for 0.5 s) and for every sleeping crate once a simulated second: asleep,
// it is no deeper in a static body than the slop (an island falls asleep only within it,
// docs/sleeping.md); awake and at rest, it is not deep in one, "deep" meaning more than a
// tenth of its half extent, the depth at which docs/events.md calls a body crushed (a
// lift may be pressing it into a platform, which the solver cannot undo).
//
// Memory: VmRSS and VmHWM (/proc/self/status) are read every simulated minute after a
// warm-up (two minutes, or half the run if shorter), and must stay within kRssToleranceKiB
// of their value at the end of it. Under AddressSanitizer, whose quarantine keeps freed
// memory for a while, RSS says nothing about leaks (LeakSanitizer checks them there), so
// the check is skipped.
//
// Exit status 0 if all held, 1 at the first broken invariant (with a message), 2 for bad
// options.
#include "invariants.hpp"

#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "shared/random.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace {

using namespace jostle;

constexpr float kDt = 1.0f / 60.0f;
constexpr int kStepsPerMinute = 60 * 60;

// The level: 160 columns and 40 rows of 16-unit tiles, y growing downward.
constexpr int kColumns = 160;
constexpr int kRows = 40;
constexpr float kTile = 16.0f;
constexpr float kWidth = kColumns * kTile;
constexpr float kHeight = kRows * kTile;
// Rows of platforms, whose tiles are dug and rebuilt.
constexpr int kPlatformRows[] = {12, 22, 30};

// The crowd: crates rain in while there are fewer than kTargetCrates, and live 20 to 90
// simulated seconds, long enough for piles to fall asleep. The rain alone would fill the
// level in 17 s; lifetimes and holes in the floor keep the count moving around the target.
constexpr std::size_t kTargetCrates = 3000;
constexpr int kSpawnPerStep = 3;

// A body is at rest, as docs/sleeping.md counts it, when slower than this many half
// extents per second and moved no further than that in the step.
constexpr float kRestSpeed = 0.05f;
constexpr float kTimeToRest = 0.5f;
// "Deep": the depth at which a kinematic body is said to crush a dynamic one, a tenth of
// its half extent along the push (docs/events.md, kCrushDepth in the solver).
constexpr float kDeep = 0.1f;

// Memory may grow this much after the warm-up, of RSS and of its peak. A step allocates
// nothing once its buffers have grown to the busiest step seen, so what is left is the
// allocator's noise (glibc keeps freed chunks in its bins and trims the top of the heap in
// steps of 128 KiB) and a busier moment than the warm-up saw growing a buffer for good:
// about 0.1 MiB over the hour of scripts/soak.sh. 1 MiB is ten times that, and a leak of
// 5 bytes a step (a 32-byte block every six steps) is more over the hour.
constexpr long kRssToleranceKiB = 1024;

struct Memory {
    long rssKiB = 0;
    long hwmKiB = 0;
};

Memory readMemory() {
    Memory m;
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind("VmRSS:", 0) == 0)
            m.rssKiB = std::atol(line.c_str() + 6);
        else if (line.rfind("VmHWM:", 0) == 0)
            m.hwmKiB = std::atol(line.c_str() + 6);
    }
    return m;
}

constexpr bool kAddressSanitizer =
#if defined(__SANITIZE_ADDRESS__)
    true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
    true;
#else
    false;
#endif
#else
    false;
#endif

[[noreturn]] void fail(long step, const std::string& what) {
    std::fprintf(stderr, "jostle-soak: FAILED at step %ld (%.2f simulated minutes): %s\n", step,
                 static_cast<double>(step) / kStepsPerMinute, what.c_str());
    std::exit(1);
}

struct Crate {
    BodyId id;
    long deathStep = 0;
    Vec2 last;
    float restTime = 0.0f;
    bool checkedAtRest = false;
};

class Soak {
public:
    Soak(int minutes, std::uint32_t seed) : minutes_(minutes), random_(seed) {}

    int run() {
        buildLevel();
        const long steps = static_cast<long>(minutes_) * kStepsPerMinute;
        const long warmUp = std::min<long>(2 * kStepsPerMinute, steps / 2);
        const auto start = std::chrono::steady_clock::now();
        for (step_ = 1; step_ <= steps; ++step_) {
            disturb();
            world_.step(kDt);
            query();
            check();
            if (step_ % kStepsPerMinute == 0 || step_ == warmUp)
                minute(step_ >= warmUp);
        }
        const double wall =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        summary(steps, wall);
        return 0;
    }

private:
    int minutes_;
    shared::Random random_;
    World world_{WorldDef{.gravity = {0, 800}}};
    TileMapId level_;
    std::vector<BodyId> lifts_;
    std::vector<Crate> crates_;
    std::vector<BodyId> graveyard_; // the last destroyed handles, to check they stay stale
    std::size_t graveyardNext_ = 0;
    std::vector<std::pair<int, long>> floorHoles_; // column, step at which it closes
    long step_ = 0;

    // What happened, for the summary.
    long created_ = 0, destroyed_ = 0, fellOut_ = 0, tileChanges_ = 0, kicks_ = 0;
    long wakes_ = 0, queries_ = 0, restChecks_ = 0, fellAsleep_ = 0;
    long beyondSlop_ = 0;
    std::size_t peakCrates_ = 0, peakBodies_ = 0, peakAsleep_ = 0;
    float worstRestDepth_ = 0.0f; // in half extents
    std::optional<Memory> baseline_;
    Memory last_;
    long maxRssKiB_ = 0;

    // --- The level ---------------------------------------------------------------------

    void buildLevel() {
        TileMapDef map;
        map.tile = kTile;
        for (int row = 0; row < kRows; ++row) {
            std::string text(kColumns, '.');
            text.front() = text.back() = '#';
            if (row >= kRows - 2)
                text.assign(kColumns, '#');
            for (int platform : kPlatformRows)
                if (row == platform)
                    for (int column = 8; column < kColumns - 8; ++column)
                        if ((column / 24) % 2 == (platform / 10) % 2)
                            text[static_cast<std::size_t>(column)] = '#';
            map.rows.push_back(text);
        }
        level_ = createTileMap(world_, map);
        // Lifts between the platforms, going up and down.
        for (int i = 0; i < 4; ++i)
            lifts_.push_back(world_.createBody({.type = BodyType::Kinematic,
                                                .x = 300.0f + 600.0f * static_cast<float>(i),
                                                .y = 400,
                                                .hw = 40,
                                                .hh = 6,
                                                .vy = i % 2 == 0 ? 60.0f : -60.0f}));
    }

    // --- What changes the world each step -----------------------------------------------

    void disturb() {
        spawn();
        expire();
        if (step_ % 120 == 0)
            turnLifts();
        if (step_ % 20 == 0)
            toggleTile(kPlatformRows[random_.between(0, 2)], random_.between(8, kColumns - 9));
        if (step_ % 600 == 0)
            openFloor();
        closeFloor();
        if (step_ % 90 == 0)
            kick();
        if (step_ % 300 == 0)
            wakeSome();
    }

    void spawn() {
        for (int i = 0; i < kSpawnPerStep && crates_.size() < kTargetCrates; ++i) {
            BodyDef def;
            def.x = random_.uniform(2 * kTile + 10, kWidth - 2 * kTile - 10);
            def.y = random_.uniform(-300, -20);
            def.hw = random_.uniform(3, 9);
            def.hh = random_.uniform(3, 9);
            def.vx = random_.uniform(-50, 50);
            def.bounce = random_.uniform(0, 0.3f);
            def.friction = random_.uniform(0.2f, 0.8f);
            def.bullet = random_.between(0, 99) == 0;
            const BodyId id = world_.createBody(def);
            crates_.push_back(
                {id, step_ + random_.between(20 * 60, 90 * 60), {def.x, def.y}, 0.0f, false});
            ++created_;
        }
        peakCrates_ = std::max(peakCrates_, crates_.size());
        peakBodies_ = std::max(peakBodies_, world_.bodyCount());
    }

    void expire() {
        std::size_t kept = 0;
        for (Crate& crate : crates_) {
            const bool out = world_.position(crate.id).y > kHeight + 200;
            if (step_ >= crate.deathStep || out) {
                world_.destroyBody(crate.id);
                bury(crate.id);
                ++destroyed_;
                fellOut_ += out;
            } else {
                crates_[kept++] = crate;
            }
        }
        crates_.resize(kept);
    }

    void bury(BodyId id) {
        if (graveyard_.size() < 256)
            graveyard_.push_back(id);
        else
            graveyard_[graveyardNext_++ % graveyard_.size()] = id;
    }

    void turnLifts() {
        for (BodyId lift : lifts_)
            world_.setVelocity(lift, -world_.velocity(lift));
    }

    /// Whether no crate overlaps the tile cell: a game does not build a wall through a
    /// crate (the crate could be left inside it, with tiles all round, for good).
    bool clearOfCrates(int column, int row) const {
        const Vec2 centre{(static_cast<float>(column) + 0.5f) * kTile,
                          (static_cast<float>(row) + 0.5f) * kTile};
        for (BodyId id : queryBox(world_, centre, {kTile / 2, kTile / 2}))
            if (world_.type(id) == BodyType::Dynamic)
                return false;
        return true;
    }

    void toggleTile(int row, int column) {
        const bool solid = isSolid(world_, level_, column, row);
        if (!solid && !clearOfCrates(column, row))
            return;
        setTile(world_, level_, column, row, !solid);
        ++tileChanges_;
    }

    /// A hole three tiles wide in the floor, closed again five seconds later: what stood
    /// there falls out of the level.
    void openFloor() {
        const int column = random_.between(4, kColumns - 8);
        for (int row = kRows - 2; row < kRows; ++row)
            for (int c = column; c < column + 3; ++c) {
                setTile(world_, level_, c, row, false);
                ++tileChanges_;
            }
        floorHoles_.push_back({column, step_ + 300});
    }

    void closeFloor() {
        for (auto it = floorHoles_.begin(); it != floorHoles_.end();) {
            bool clear = true;
            for (int row = kRows - 2; row < kRows; ++row)
                for (int c = it->first; c < it->first + 3; ++c)
                    clear = clear && clearOfCrates(c, row);
            if (step_ < it->second || !clear) { // closed once nothing is in the way
                ++it;
                continue;
            }
            for (int row = kRows - 2; row < kRows; ++row)
                for (int c = it->first; c < it->first + 3; ++c) {
                    setTile(world_, level_, c, row, true);
                    ++tileChanges_;
                }
            it = floorHoles_.erase(it);
        }
    }

    /// A crate kicked upward: its pile wakes.
    void kick() {
        if (crates_.empty())
            return;
        const Crate& crate = crates_[static_cast<std::size_t>(
            random_.between(0, static_cast<int>(crates_.size()) - 1))];
        world_.setVelocity(crate.id, {random_.uniform(-100, 100), -300});
        ++kicks_;
    }

    void wakeSome() {
        for (int i = 0; i < 50 && !crates_.empty(); ++i) {
            world_.wake(crates_[static_cast<std::size_t>(
                                    random_.between(0, static_cast<int>(crates_.size()) - 1))]
                            .id);
            ++wakes_;
        }
    }

    // --- Queries -------------------------------------------------------------------------

    void query() {
        for (int i = 0; i < 4; ++i) {
            const float x = random_.uniform(0, kWidth);
            for (const RayHit& hit : rayCastAll(world_, {x, -400}, {x, kHeight + 100}))
                requireLive(hit.body, "rayCastAll");
        }
        const Vec2 centre{random_.uniform(0, kWidth), random_.uniform(0, kHeight)};
        for (BodyId id : queryBox(world_, centre, {40, 40}))
            requireLive(id, "queryBox");
        const MoveResult moved =
            moveAndSlide(world_, centre, {6, 10}, {random_.uniform(-30, 30), 20});
        if (!isFinite(moved.centre))
            fail(step_, "moveAndSlide: a centre that is not finite");
        for (const MoveHit& hit : moved.hits)
            requireLive(hit.body, "moveAndSlide");
        queries_ += 6;
    }

    void requireLive(BodyId id, const char* query) {
        if (!world_.isValid(id))
            fail(step_,
                 std::string(query) + " reported " + check::describe(id) + ", which is not valid");
    }

    // --- Invariants ----------------------------------------------------------------------

    void check() {
        if (auto problem = check::finiteState(world_))
            fail(step_, *problem);
        const std::size_t tiles = tileMapBodies(world_, level_).size();
        if (world_.bodyCount() != crates_.size() + lifts_.size() + tiles)
            fail(step_, "bodyCount " + std::to_string(world_.bodyCount()) + ", expected " +
                            std::to_string(crates_.size() + lifts_.size() + tiles));
        for (BodyId id : graveyard_)
            if (world_.isValid(id))
                fail(step_, check::describe(id) + " is valid after being destroyed");
        std::size_t asleep = 0;
        const bool sweep = step_ % 60 == 0;
        for (Crate& crate : crates_) {
            if (!world_.isValid(crate.id))
                fail(step_, check::describe(crate.id) + " is stale though never destroyed");
            const Vec2 p = world_.position(crate.id), h = world_.halfExtents(crate.id);
            const float slow = kRestSpeed * std::min(h.x, h.y);
            const bool awake = world_.isAwake(crate.id);
            const bool still = !awake || (length(world_.velocity(crate.id)) < slow &&
                                          length(p - crate.last) <= slow * kDt);
            crate.restTime = still ? crate.restTime + kDt : 0.0f;
            crate.last = p;
            if (!still)
                crate.checkedAtRest = false;
            asleep += !awake;
            // When it comes to rest, and then once a second while it sleeps.
            const bool cameToRest =
                !crate.checkedAtRest && (!awake || crate.restTime >= kTimeToRest);
            if (cameToRest || (sweep && !awake)) {
                fellAsleep_ += cameToRest && !awake;
                crate.checkedAtRest = true;
                checkRest(crate.id);
            }
        }
        peakAsleep_ = std::max(peakAsleep_, asleep);
        // The order of bodies() is creation order: the crates', in particular.
        if (sweep) {
            std::size_t next = 0;
            for (BodyId id : world_.bodies())
                if (next < crates_.size() && id == crates_[next].id)
                    ++next;
            if (next != crates_.size())
                fail(step_, "bodies() does not list the crates in creation order");
        }
    }

    void checkRest(BodyId id) {
        ++restChecks_;
        const Vec2 h = world_.halfExtents(id);
        const float half = std::min(h.x, h.y);
        // Any overlap with a static body at all (an allowance of minus infinity), to
        // report the deepest.
        if (const std::optional<check::Penetration> deepest =
                check::deepInStatic(world_, id, -std::numeric_limits<float>::infinity()))
            worstRestDepth_ = std::max(worstRestDepth_, deepest->depth / half);
        const std::optional<check::Penetration> p = check::deepInStatic(world_, id);
        if (!p)
            return; // within the slop
        ++beyondSlop_;
        if (!world_.isAwake(id) || p->depth > kDeep * half)
            fail(step_, check::describe(id) + " at rest at " +
                            check::describe(world_.position(id)) + ", half " + check::describe(h) +
                            ", is " + std::to_string(p->depth) + " deep in static " +
                            check::describe(p->into) +
                            (world_.isAwake(id) ? " (awake)" : " (asleep)"));
    }

    // --- Memory and the report -----------------------------------------------------------

    void minute(bool warm) {
        last_ = readMemory();
        maxRssKiB_ = std::max(maxRssKiB_, last_.rssKiB);
        if (warm && !baseline_)
            baseline_ = last_;
        std::printf("minute %5.1f: %5zu crates (%4zu asleep), %5zu bodies, RSS %6.1f MiB, peak "
                    "%6.1f MiB\n",
                    static_cast<double>(step_) / kStepsPerMinute, crates_.size(), countAsleep(),
                    world_.bodyCount(), static_cast<double>(last_.rssKiB) / 1024,
                    static_cast<double>(last_.hwmKiB) / 1024);
        std::fflush(stdout);
        if (!warm || !baseline_ || kAddressSanitizer)
            return;
        if (last_.rssKiB > baseline_->rssKiB + kRssToleranceKiB ||
            last_.hwmKiB > baseline_->hwmKiB + kRssToleranceKiB)
            fail(step_, "memory grew: RSS " + std::to_string(baseline_->rssKiB) + " -> " +
                            std::to_string(last_.rssKiB) + " KiB, peak " +
                            std::to_string(baseline_->hwmKiB) + " -> " +
                            std::to_string(last_.hwmKiB) + " KiB (tolerance " +
                            std::to_string(kRssToleranceKiB) + " KiB)");
    }

    std::size_t countAsleep() const {
        std::size_t n = 0;
        for (const Crate& crate : crates_)
            n += !world_.isAwake(crate.id);
        return n;
    }

    void summary(long steps, double wall) {
        const Memory end = readMemory();
        std::printf("\njostle-soak: all invariants held\n");
        std::printf("  steps              %ld (%.1f simulated minutes at 1/60 s)\n", steps,
                    static_cast<double>(steps) / kStepsPerMinute);
        std::printf("  crates created     %ld, destroyed %ld (%ld fell out of the level)\n",
                    created_, destroyed_, fellOut_);
        std::printf("  peak               %zu crates, %zu bodies, %zu crates asleep at once\n",
                    peakCrates_, peakBodies_, peakAsleep_);
        std::printf("  disturbances       %ld tile changes, %ld kicks, %ld crates woken by hand\n",
                    tileChanges_, kicks_, wakes_);
        std::printf("  queries            %ld\n", queries_);
        std::printf("  rest checks        %ld (%ld on falling asleep)\n", restChecks_, fellAsleep_);
        std::printf("  deepest at rest    %.4f half extents in a static body (fails beyond the "
                    "slop, %.2f, asleep, and beyond %.2f awake); %ld times beyond the slop\n",
                    static_cast<double>(worstRestDepth_),
                    static_cast<double>(world_.physicalOptions().slop), static_cast<double>(kDeep),
                    beyondSlop_);
        if (baseline_)
            std::printf("  memory             RSS %ld KiB after warm-up, %ld KiB at the end "
                        "(max %ld); peak (VmHWM) %ld -> %ld KiB; tolerance %ld KiB%s\n",
                        baseline_->rssKiB, end.rssKiB, maxRssKiB_, baseline_->hwmKiB, end.hwmKiB,
                        kRssToleranceKiB,
                        kAddressSanitizer ? " (AddressSanitizer: not checked)" : "");
        std::printf("  wall time          %.1f s\n", wall);
    }
};

} // namespace

int main(int argc, char** argv) {
    int minutes = 60;
    std::uint32_t seed = 1;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if ((arg == "--minutes" || arg == "--seed") && i + 1 < argc) {
            char* end = nullptr;
            const long value = std::strtol(argv[++i], &end, 10);
            if (*end != '\0' || value < 1 || value > 100000) {
                std::fprintf(stderr, "jostle-soak: %s: expected a whole number >= 1\n",
                             arg.c_str());
                return 2;
            }
            if (arg == "--minutes")
                minutes = static_cast<int>(value);
            else
                seed = static_cast<std::uint32_t>(value);
        } else {
            std::fprintf(stderr, "usage: jostle-soak [--minutes N] [--seed S]\n");
            return 2;
        }
    }
    return Soak(minutes, seed).run();
}
