// libFuzzer: bytes as a program of calls to the public API.
//
// The first byte picks one of two modes:
//
// - Chaos (most inputs): a sequence of operations, each drawn from the bytes: create
//   bodies of any type, size and place (NaN, infinity, zeros and extreme magnitudes
//   included, on both sides of the edges of math.hpp's range), destroy them, call every setter,
//   step with good and bad dt, query, make and change tile maps, change the world's settings, use
//   stale, null and forged handles, and install pre-solve callbacks that veto, destroy, create,
//   query, throw or try to step. Every call is held to its documented contract: bad arguments throw
//   jostle::Error and leave the world exactly as it was, good ones do not throw and do what they
//   say. The fuzzer keeps its own list of the live bodies, in creation order, and after each step
//   checks that the world agrees with it and that every state is finite
//   (tests/fuzz/invariants.hpp). A first byte of 0xFF mixes in the operations of characters,
//   forces and move(); 0xFE those and ramps: ramp tiles in maps, setTile with any character,
//   tileOf, and the floorAngle and snapDown of bodies.
//
// - Settled (first byte a multiple of 8): dynamic boxes dropped on a static floor (one
//   box, boxes edge to edge, a tile map, or a box with walls) in the physical model with
//   default options and gravity down, then stepped for seconds with nothing else done.
//   Every body that has come to rest must sit inside no static body deeper than the slop
//   lets it (check::deepInStatic).
//
// Anything that breaks a contract aborts with a message: libFuzzer saves the input.
// A finding that waits for a design decision may be set aside (tests/fuzz/open/
// README.md says how; none is now). JOSTLE_FUZZ_VERBOSE and JOSTLE_FUZZ_MODE are
// described where they are read.
#include "invariants.hpp"

#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cfenv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace {

using namespace jostle;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// JOSTLE_FUZZ_VERBOSE=1 prints what an input does (to turn a finding into a unit test),
/// 2 also the bodies before every step, 3 also traps where a step makes a NaN.
int verbosity() {
    static const int level =
        std::getenv("JOSTLE_FUZZ_VERBOSE") ? std::atoi(std::getenv("JOSTLE_FUZZ_VERBOSE")) : 0;
    return level;
}

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_api finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

// --- Reading the program -------------------------------------------------------------

/// The bytes as the values a program passes. Exhausted input reads as zeros, which every
/// reader maps to an ordinary value.
class Input {
public:
    Input(const std::uint8_t* data, std::size_t size) : fdp_(data, size) {}

    bool done() { return fdp_.remaining_bytes() == 0; }
    std::uint8_t byte() { return fdp_.ConsumeIntegral<std::uint8_t>(); }
    bool flag() { return fdp_.ConsumeBool(); }
    int integer(int lo, int hi) { return fdp_.ConsumeIntegralInRange(lo, hi); }
    std::uint32_t bits() { return fdp_.ConsumeIntegral<std::uint32_t>(); }

    /// Mostly a number in [lo, hi], what a game would pass; sometimes a value known to
    /// break arithmetic or to lie at the edges of the range jostle works in (0, -0,
    /// denormals, 1e-9, 1e9 and beyond, FLT_MAX, infinities, NaN); sometimes any bit
    /// pattern.
    float number(float lo, float hi) {
        const std::uint8_t kind = byte();
        if (kind < 210)
            return lo +
                   (hi - lo) * static_cast<float>(fdp_.ConsumeIntegral<std::uint16_t>()) / 65535.0f;
        return kind < 250 ? special() : std::bit_cast<float>(bits());
    }

    float special() {
        static constexpr std::array<float, 29> values = {0.0f,
                                                         -0.0f,
                                                         1.0f,
                                                         -1.0f,
                                                         0.5f,
                                                         2.0f,
                                                         -0.5f,
                                                         1e-45f, // the smallest denormal
                                                         std::numeric_limits<float>::min(),
                                                         1e-30f,
                                                         1e-9f, // kMinMagnitude
                                                         9.9e-10f,
                                                         2e-9f, // the smallest tile
                                                         1e-7f,
                                                         1e-6f,
                                                         1e6f,
                                                         1e9f, // kMaxMagnitude
                                                         1.01e9f,
                                                         -1e9f,
                                                         1e18f,
                                                         1e30f,
                                                         -1e30f,
                                                         3e38f,
                                                         std::numeric_limits<float>::max(),
                                                         -std::numeric_limits<float>::max(),
                                                         kInf,
                                                         -kInf,
                                                         kNaN,
                                                         -kNaN};
        return values[byte() % values.size()];
    }

    Vec2 vec(float lo, float hi) { return {number(lo, hi), number(lo, hi)}; }

private:
    FuzzedDataProvider fdp_;
};

// --- Comparing without NaN's help ------------------------------------------------------

bool same(float a, float b) {
    return std::bit_cast<std::uint32_t>(a) == std::bit_cast<std::uint32_t>(b);
}
bool same(Vec2 a, Vec2 b) {
    return same(a.x, b.x) && same(a.y, b.y);
}

/// True for a size, density, mass or dt jostle accepts (math.hpp): in [1e-9, 1e9].
bool isSize(float v) {
    return inRange(v) && v >= kMinMagnitude;
}

bool isUnitAxis(Vec2 n) {
    return (std::abs(n.x) == 1.0f && n.y == 0.0f) || (n.x == 0.0f && std::abs(n.y) == 1.0f);
}

bool isUnit(Vec2 n) {
    return isFinite(n) && std::abs(length(n) - 1.0f) <= 1e-5f;
}

// --- Ramp tiles, written down again from tilemap.hpp ------------------------------------

/// Ramp characters as tilemap.hpp draws them (a y-down world: rows top first): floors are
/// solid below their slope, ceilings above.
constexpr std::string_view kFloorRamps = "/\\rRLl";
constexpr std::string_view kCeilingRamps = "7FcCDd";

bool isRampChar(char tile) {
    return kFloorRamps.find(tile) != std::string_view::npos ||
           kCeilingRamps.find(tile) != std::string_view::npos;
}

bool isTileChar(char tile) {
    return tile == '#' || tile == '.' || isRampChar(tile);
}

bool hasRamp(const std::vector<std::string>& rows) {
    for (const std::string& row : rows)
        if (std::any_of(row.begin(), row.end(), isRampChar))
            return true;
    return false;
}

/// Where a ramp's outline leaves `point`: < 0 on the solid side of its slope, > 0 on the
/// cut-away side, in units of its half extents (its box's far corners are at -2 and 2).
double slopeSide(Vec2 centre, Vec2 half, Vec2 slope, double x, double y) {
    return static_cast<double>(slope.x) * (x - static_cast<double>(centre.x)) /
               static_cast<double>(half.x) +
           static_cast<double>(slope.y) * (y - static_cast<double>(centre.y)) /
               static_cast<double>(half.y);
}

/// Everything observable about a world through the API, as bits: two fingerprints are
/// equal when a failed call changed nothing.
std::vector<std::uint32_t> fingerprint(const World& world, const std::vector<TileMapId>& maps) {
    std::vector<std::uint32_t> out;
    auto f = [&](float v) { out.push_back(std::bit_cast<std::uint32_t>(v)); };
    auto v2 = [&](Vec2 v) {
        f(v.x);
        f(v.y);
    };
    v2(world.gravity());
    f(world.maxVelocity());
    out.push_back(static_cast<std::uint32_t>(world.solver()));
    out.push_back(world.sleeping());
    const ClassicOptions c = world.classicOptions();
    out.push_back(static_cast<std::uint32_t>(c.mass | c.coulomb << 1 | c.ccd << 2));
    const PhysicalOptions p = world.physicalOptions();
    out.push_back(static_cast<std::uint32_t>(p.velocityIterations));
    out.push_back(static_cast<std::uint32_t>(p.positionIterations));
    f(p.slop);
    f(p.correction);
    f(p.restitutionThreshold);
    out.push_back(static_cast<std::uint32_t>(p.frictionMix));
    for (BodyId id : world.bodies()) {
        out.push_back(id.index);
        out.push_back(id.generation);
        const BodyDef d = world.bodyDef(id);
        out.push_back(static_cast<std::uint32_t>(d.type));
        for (float v :
             {d.x, d.y, d.hw, d.hh, d.vx, d.vy, d.bounce, d.friction, d.mass, d.density,
              d.gravityScale, d.damping, d.oneWay.x, d.oneWay.y, d.floorAngle, d.snapDown})
            f(v);
        out.push_back(
            static_cast<std::uint32_t>(d.bullet | d.sensor << 1 | world.isAwake(id) << 2));
        out.push_back(d.category);
        out.push_back(d.mask);
        out.push_back(static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(d.userData)));
        v2(world.separation(id));
    }
    for (TileMapId map : maps) {
        out.push_back(world.isValid(map));
        if (!world.isValid(map))
            continue;
        for (const std::string& row : tileMapDef(world, map).rows)
            for (char tile : row)
                out.push_back(static_cast<std::uint32_t>(tile));
        for (BodyId body : tileMapBodies(world, map))
            out.push_back(body.index);
    }
    return out;
}

// --- The documented rules, written down again from the headers ---------------------------

/// body.hpp's rules for a BodyDef, math.hpp's range, and that a static body does not move.
bool documentedValid(const BodyDef& d) {
    if (d.type != BodyType::Static && d.type != BodyType::Kinematic && d.type != BodyType::Dynamic)
        return false;
    for (float v : {d.x, d.y, d.hw, d.hh, d.vx, d.vy, d.bounce, d.friction, d.mass, d.density,
                    d.gravityScale, d.damping, d.oneWay.x, d.oneWay.y})
        if (!inRange(v))
            return false;
    if (!(isSize(d.hw) && isSize(d.hh) && isSize(d.density) && (d.mass == 0 || isSize(d.mass)) &&
          d.damping >= 0))
        return false;
    if (!(d.bounce >= 0 && d.bounce <= 1 && d.friction >= 0 && d.friction <= 1))
        return false;
    if (!isValidOneWay(d.oneWay))
        return false;
    if (!(d.floorAngle >= 0 && d.floorAngle < 90 && inRange(d.snapDown) && d.snapDown >= 0))
        return false;
    return !(d.type == BodyType::Static && (d.vx != 0 || d.vy != 0));
}

bool documentedValid(const WorldDef& d) {
    const PhysicalOptions& p = d.physical;
    return inRange(d.gravity) && !std::isnan(d.maxVelocity) && d.maxVelocity > 0 &&
           (d.solver == Solver::Classic || d.solver == Solver::Physical) &&
           p.velocityIterations >= 1 && p.velocityIterations <= 1000 && p.positionIterations >= 0 &&
           p.positionIterations <= 1000 && p.slop >= 0 && p.slop <= 0.5f && p.correction > 0 &&
           p.correction <= 1 && std::isfinite(p.restitutionThreshold) &&
           p.restitutionThreshold >= 0 &&
           (p.frictionMix == FrictionMix::Min || p.frictionMix == FrictionMix::GeometricMean);
}

// --- The program ---------------------------------------------------------------------------

/// Thrown by a pre-solve callback to see the world survive an exception out of step().
struct CallbackThrow {};

class Program {
public:
    /// `characters`: the operations of characters, forces and move() are in the mix too;
    /// `ramps` (with characters): ramp tiles, setTile with any character, tileOf, and the
    /// floorAngle and snapDown of bodies. Each came after the corpus was gathered: without
    /// them, an input means what it always meant.
    Program(Input& in, bool characters, bool ramps)
        : in_(in), characters_(characters || ramps), ramps_(ramps) {}

    void run() {
        makeWorld();
        for (int op = 0; op < kMaxOps && !in_.done(); ++op) {
            const std::uint8_t pick = in_.byte();
            const int kind = characters_ ? pick % 13 : pick % 12;
            if (verbosity() >= 1)
                std::fprintf(stderr, "op %d: %s\n", op, kOpNames[kind]);
            switch (kind) {
            case 0:
            case 1:
                createBody();
                break;
            case 2:
                destroyBody();
                break;
            case 3:
            case 4:
                setBody();
                break;
            case 5:
            case 6:
                step();
                break;
            case 7:
                query();
                break;
            case 8:
                tileMapOp();
                break;
            case 9:
                worldSetting();
                break;
            case 10:
                installCallback();
                break;
            case 11:
                readBody();
                break;
            case 12:
                characterOp();
                break;
            }
            // No call, good or bad, leaves a number that is not finite behind.
            if (auto problem = check::finiteState(world_))
                finding(std::string("after ") + kOpNames[kind] + ": " + *problem);
        }
        step();
        if (verbosity() >= 1)
            std::fprintf(stderr, "chaos: %zu bodies live, %zu destroyed, %zu maps, %d steps\n",
                         live_.size(), dead_.size(), maps_.size(), steps_);
    }

private:
    static constexpr int kMaxOps = 400;
    static constexpr const char* kOpNames[13] = {
        "createBody", "createBody", "destroyBody",   "set",      "set",  "step",     "step",
        "query",      "tile map",   "world setting", "callback", "read", "character"};
    static constexpr std::size_t kMaxBodies = 96;
    static constexpr std::size_t kMaxMaps = 3;
    static constexpr std::size_t kMaxDead = 32;

    Input& in_;
    bool characters_;
    bool ramps_;
    World world_;
    std::vector<BodyId> live_; ///< the fuzzer's own list, in creation order
    std::vector<BodyId> dead_; ///< the last kMaxDead destroyed handles
    /// The world's serial number (BodyId::world), as its bodies carry it: forged handles
    /// are of this world or another.
    std::uint32_t serial_ = 0;
    struct Map {
        TileMapId id;
        std::vector<std::string> rows;
    };
    std::vector<Map> maps_;
    std::vector<TileMapId> deadMaps_;
    /// Maps one of whose bodies the program changed or destroyed: their boxes no longer
    /// cover their tiles exactly, until a rebuild that need not come.
    std::vector<TileMapId> tampered_;
    /// Every body with a shape (a ramp) ever created, as index << 32 | generation: its
    /// contacts' normals need not be along x or y, even in the events of its destruction.
    std::unordered_set<std::uint64_t> shaped_;

    // The installed pre-solve callback's behaviour and its bookkeeping for one step.
    int callbackMode_ = 0;
    std::uint8_t callbackParam_ = 0;
    int callbackCalls_ = 0;
    bool inStep_ = false;
    int steps_ = 0; ///< completed, for the summary

    // --- Bookkeeping ---------------------------------------------------------------------

    void buried(BodyId id) {
        live_.erase(std::find(live_.begin(), live_.end(), id));
        dead_.push_back(id);
        if (dead_.size() > kMaxDead)
            dead_.erase(dead_.begin());
    }

    /// The program is about to change or destroy `id`, which may belong to a tile map.
    void tamper(BodyId id) {
        if (world_.isValid(id))
            if (const TileMapId map = tileMapOf(world_, id); !map.isNull())
                tampered_.push_back(map);
    }

    bool isLive(BodyId id) const {
        return std::find(live_.begin(), live_.end(), id) != live_.end();
    }

    std::vector<TileMapId> mapIds() const {
        std::vector<TileMapId> ids;
        for (const Map& m : maps_)
            ids.push_back(m.id);
        return ids;
    }

    std::vector<std::uint32_t> snapshot() const { return fingerprint(world_, mapIds()); }

    void requireUnchanged(const std::vector<std::uint32_t>& before, const char* call) {
        if (snapshot() != before)
            finding(std::string(call) + " threw jostle::Error but changed the world");
    }

    /// Runs `call`, which must throw jostle::Error exactly when `valid` is false, and
    /// leave the world unchanged when it does. Returns true if it succeeded.
    template <class Call> bool expect(bool valid, const char* name, Call&& call) {
        // Only a call that must fail needs the world's fingerprint: a valid one that fails
        // is a finding whatever it changed.
        const std::vector<std::uint32_t> before = valid ? std::vector<std::uint32_t>{} : snapshot();
        try {
            call();
        } catch (const Error& error) {
            if (valid)
                finding(std::string(name) + " refused a valid call: " + error.what());
            requireUnchanged(before, name);
            return false;
        }
        if (!valid)
            finding(std::string(name) + " accepted an invalid call");
        return true;
    }

    /// After a call that may create bodies (appended at the end) and destroy some of
    /// `mayGo`: the fuzzer's list catches up, and must then equal world.bodies().
    void catchUp(const char* after, const std::vector<BodyId>& mayGo) {
        std::vector<BodyId> kept, gone;
        for (BodyId id : live_) {
            if (world_.isValid(id))
                kept.push_back(id);
            else if (std::find(mayGo.begin(), mayGo.end(), id) == mayGo.end())
                finding(std::string(after) + " destroyed " + check::describe(id));
            else
                gone.push_back(id);
        }
        for (BodyId id : gone)
            buried(id);
        const std::span<const BodyId> listed = world_.bodies();
        if (listed.size() < kept.size() || !std::equal(kept.begin(), kept.end(), listed.begin()))
            finding(std::string(after) + ": bodies() lost the creation order");
        for (std::size_t i = kept.size(); i < listed.size(); ++i)
            if (const BodyDef d = world_.bodyDef(listed[i]); d.slope != Vec2{} || d.radius > 0)
                shaped_.insert(std::uint64_t{listed[i].index} << 32 | listed[i].generation);
        live_.assign(listed.begin(), listed.end());
        if (!listed.empty())
            serial_ = listed.front().world;
    }

    bool isShaped(BodyId id) const {
        return shaped_.contains(std::uint64_t{id.index} << 32 | id.generation);
    }

    bool anyShaped() const {
        return std::any_of(live_.begin(), live_.end(), [&](BodyId id) { return isShaped(id); });
    }

    /// A contact's or a hit's normal: unit, and along x or y unless a body with a shape is
    /// in it (world.hpp, query.hpp).
    bool goodNormal(Vec2 n, BodyId a, BodyId b = {}) const {
        return isShaped(a) || isShaped(b) ? isUnit(n) : isUnitAxis(n);
    }

    // --- Picking handles -------------------------------------------------------------------

    BodyId pickBody() {
        const std::uint8_t kind = in_.byte();
        if (kind < 200 && !live_.empty())
            return live_[kind % live_.size()];
        if (kind < 230 && !dead_.empty())
            return dead_[kind % dead_.size()];
        if (kind < 240)
            return {};
        // Forged: any index and generation, of this world or another (bit 7 of the
        // index's bits), which may even name a live body.
        const std::uint32_t bits = in_.bits();
        return {bits % 128, in_.bits() % 4, (bits & 128) != 0 ? serial_ ^ 1 : serial_};
    }

    TileMapId pickMap() {
        const std::uint8_t kind = in_.byte();
        if (kind < 200 && !maps_.empty())
            return maps_[kind % maps_.size()].id;
        if (kind < 230 && !deadMaps_.empty())
            return deadMaps_[kind % deadMaps_.size()];
        if (kind < 240)
            return {};
        const std::uint32_t bits = in_.bits();
        return {bits % 8, in_.bits() % 4, (bits & 128) != 0 ? serial_ ^ 1 : serial_};
    }

    Map* findMap(TileMapId id) {
        for (Map& m : maps_)
            if (m.id == id)
                return &m;
        return nullptr;
    }

    // --- Making things -----------------------------------------------------------------------

    BodyType pickType() {
        const std::uint8_t b = in_.byte();
        return b < 252 ? static_cast<BodyType>(b % 3) : static_cast<BodyType>(b);
    }

    BodyDef makeBodyDef() {
        BodyDef d;
        d.type = pickType();
        d.x = in_.number(-400, 400);
        d.y = in_.number(-400, 400);
        d.hw = in_.number(0.25f, 60);
        d.hh = in_.number(0.25f, 60);
        if (d.type != BodyType::Static || in_.byte() > 240) {
            d.vx = in_.number(-600, 600);
            d.vy = in_.number(-600, 600);
        }
        const std::uint8_t extras = in_.byte();
        if (extras & 1) {
            d.bounce = in_.number(0, 1);
            d.friction = in_.number(0, 1);
        }
        if (extras & 2) {
            if (in_.flag())
                d.mass = in_.number(0.01f, 100);
            else
                d.density = in_.number(0.01f, 100);
        }
        if (extras & 4) {
            d.gravityScale = in_.number(-2, 2);
            d.damping = in_.number(0, 5);
        }
        if (extras & 8)
            d.oneWay = pickOneWay();
        if (extras & 16) {
            d.category = 1u << (in_.byte() % 4);
            d.mask = in_.bits() & 0xF;
        }
        d.bullet = (extras & 32) != 0;
        d.sensor = (extras & 192) == 192;
        if (ramps_) {
            const std::uint8_t more = in_.byte();
            if (more & 1)
                d.floorAngle = in_.number(0, 90); // 90 itself is refused: [0, 90)
            if (more & 2)
                d.snapDown = in_.number(0, 40);
        }
        return d;
    }

    Vec2 pickOneWay() {
        static constexpr std::array<Vec2, 8> normals = {Vec2{0, 0}, Vec2{0, -1},  Vec2{0, 1},
                                                        Vec2{1, 0}, Vec2{-1, 0},  Vec2{0.5f, 0},
                                                        Vec2{1, 1}, Vec2{kNaN, 0}};
        return normals[in_.byte() % normals.size()];
    }

    void makeWorld() {
        WorldDef d;
        d.gravity = {in_.flag() ? 0.0f : in_.number(-100, 100), in_.number(-1000, 1000)};
        if (in_.byte() > 200)
            d.maxVelocity = in_.number(1, 2000);
        d.solver = in_.byte() % 4 == 0 ? Solver::Classic : Solver::Physical;
        d.classic = {in_.flag(), in_.flag(), in_.flag()};
        d.sleeping = in_.byte() % 4 != 0;
        if (in_.byte() > 230) {
            d.physical.velocityIterations = in_.integer(-1, 12);
            d.physical.positionIterations = in_.integer(-1, 8);
            d.physical.slop = in_.number(0, 0.5f);
            d.physical.correction = in_.number(0, 1);
            d.physical.restitutionThreshold = in_.number(0, 100);
            d.physical.frictionMix = static_cast<FrictionMix>(in_.byte() % 3);
        }
        const bool valid = documentedValid(d);
        try {
            world_ = World(d);
        } catch (const Error& error) {
            if (valid)
                finding(std::string("World refused a valid WorldDef: ") + error.what());
            return; // keep the default world
        }
        if (!valid)
            finding("World accepted an invalid WorldDef");
    }

    void createBody() {
        const BodyDef d = makeBodyDef();
        if (live_.size() >= kMaxBodies)
            return;
        // checkBodyDef is the rule createBody applies: it must agree with the rules
        // written down above.
        const bool checked = !checkBodyDef(d).has_value();
        if (documentedValid(d) != checked)
            finding(checked ? std::string("checkBodyDef accepted an invalid BodyDef")
                            : "checkBodyDef refused a valid BodyDef: " + checkBodyDef(d)->field +
                                  ": " + checkBodyDef(d)->problem);
        const bool valid = documentedValid(d) && checked;
        if (verbosity() >= 1)
            std::fprintf(stderr,
                         "createBody: type %d at (%.9g, %.9g) half (%.9g, %.9g) v (%.9g, %.9g) "
                         "mass %.9g density %.9g floorAngle %.9g snapDown %.9g\n",
                         static_cast<int>(d.type), static_cast<double>(d.x),
                         static_cast<double>(d.y), static_cast<double>(d.hw),
                         static_cast<double>(d.hh), static_cast<double>(d.vx),
                         static_cast<double>(d.vy), static_cast<double>(d.mass),
                         static_cast<double>(d.density), static_cast<double>(d.floorAngle),
                         static_cast<double>(d.snapDown));
        BodyId id;
        if (!expect(valid, "createBody", [&] { id = world_.createBody(d); }))
            return;
        live_.push_back(id);
        if (!world_.isValid(id))
            finding("createBody returned an invalid handle");
        const BodyDef got = world_.bodyDef(id);
        if (got.type != d.type || !same({got.x, got.y}, {d.x, d.y}) ||
            !same({got.hw, got.hh}, {d.hw, d.hh}) || !same({got.vx, got.vy}, {d.vx, d.vy}) ||
            got.category != d.category || got.mask != d.mask || got.sensor != d.sensor ||
            !same(got.floorAngle, d.floorAngle) || !same(got.snapDown, d.snapDown))
            finding("bodyDef does not give back what createBody was given");
        checkList("createBody");
    }

    void destroyBody() {
        const BodyId id = pickBody();
        const bool valid = isLive(id);
        tamper(id);
        if (!expect(valid, "destroyBody", [&] { world_.destroyBody(id); }))
            return;
        if (world_.isValid(id))
            finding("destroyBody left the handle valid");
        buried(id);
        checkList("destroyBody");
    }

    /// Every setter, with its rule from world.hpp; on success the getter must agree.
    void setBody() {
        const BodyId id = pickBody();
        const bool live = isLive(id);
        tamper(id);
        const std::uint8_t which = in_.byte() % 19;
        switch (which) {
        case 0: {
            const BodyType t = pickType();
            // A ramp or segment is static or kinematic (world.hpp); a rounded body any.
            const bool ok =
                t == BodyType::Static || t == BodyType::Kinematic ||
                (t == BodyType::Dynamic && !(live && world_.bodyDef(id).slope != Vec2{}));
            if (expect(live && ok, "setType", [&] { world_.setType(id, t); }) &&
                (world_.type(id) != t || (t == BodyType::Static && world_.velocity(id) != Vec2{})))
                finding("setType did not take");
            break;
        }
        case 1: {
            const Vec2 p = in_.vec(-400, 400);
            if (expect(live && inRange(p), "setPosition", [&] { world_.setPosition(id, p); }) &&
                !same(world_.position(id), p))
                finding("setPosition did not take");
            break;
        }
        case 2: {
            const Vec2 v = in_.vec(-600, 600);
            const bool ok = inRange(v) && (!live || world_.type(id) != BodyType::Static ||
                                           (v.x == 0 && v.y == 0));
            if (expect(live && ok, "setVelocity", [&] { world_.setVelocity(id, v); }) &&
                !same(world_.velocity(id), v))
                finding("setVelocity did not take");
            break;
        }
        case 3: {
            const Vec2 h = in_.vec(0.25f, 60);
            // No smaller than a rounded body's radius (world.hpp).
            const float radius = live ? world_.bodyDef(id).radius : 0.0f;
            const bool ok = isSize(h.x) && isSize(h.y) && std::min(h.x, h.y) >= radius;
            if (expect(live && ok, "setHalfExtents", [&] { world_.setHalfExtents(id, h); }) &&
                !same(world_.halfExtents(id), h))
                finding("setHalfExtents did not take");
            break;
        }
        case 4: {
            const float b = in_.number(0, 1);
            if (expect(live && b >= 0 && b <= 1, "setBounce", [&] { world_.setBounce(id, b); }) &&
                !same(world_.bounce(id), b))
                finding("setBounce did not take");
            break;
        }
        case 5: {
            const float f = in_.number(0, 1);
            if (expect(live && f >= 0 && f <= 1, "setFriction",
                       [&] { world_.setFriction(id, f); }) &&
                !same(world_.friction(id), f))
                finding("setFriction did not take");
            break;
        }
        case 6: {
            const float m = in_.number(0.01f, 100);
            if (expect(live && isSize(m), "setMass", [&] { world_.setMass(id, m); }) &&
                world_.type(id) == BodyType::Dynamic && !same(world_.mass(id), m))
                finding("setMass did not take");
            break;
        }
        case 7: {
            const float d = in_.number(0.01f, 100);
            expect(live && isSize(d), "setDensity", [&] { world_.setDensity(id, d); });
            break;
        }
        case 8: {
            const float g = in_.number(-2, 2);
            if (expect(live && inRange(g), "setGravityScale",
                       [&] { world_.setGravityScale(id, g); }) &&
                !same(world_.gravityScale(id), g))
                finding("setGravityScale did not take");
            break;
        }
        case 9: {
            const float d = in_.number(0, 5);
            if (expect(live && inRange(d) && d >= 0, "setDamping",
                       [&] { world_.setDamping(id, d); }) &&
                !same(world_.damping(id), d))
                finding("setDamping did not take");
            break;
        }
        case 10: {
            const bool b = in_.flag();
            if (expect(live, "setBullet", [&] { world_.setBullet(id, b); }) &&
                world_.isBullet(id) != b)
                finding("setBullet did not take");
            break;
        }
        case 11:
            if (expect(live, "wake", [&] { world_.wake(id); }) && !world_.isAwake(id))
                finding("wake left the body asleep");
            break;
        case 12: {
            void* data = reinterpret_cast<void*>(static_cast<std::uintptr_t>(in_.bits()));
            if (expect(live, "setUserData", [&] { world_.setUserData(id, data); }) &&
                world_.userData(id) != data)
                finding("setUserData did not take");
            break;
        }
        case 13: {
            const Vec2 n = pickOneWay();
            // A shaped body is never one-way (world.hpp).
            const bool ok = isValidOneWay(n) && (n == Vec2{} || !isShaped(id));
            if (expect(live && ok, "setOneWay", [&] { world_.setOneWay(id, n); }) &&
                !same(world_.oneWay(id), n))
                finding("setOneWay did not take");
            break;
        }
        case 14: {
            const float s = in_.number(0, 2);
            const bool dynamic = live && world_.type(id) == BodyType::Dynamic;
            expect(dynamic && std::isfinite(s) && s >= 0, "dropThrough",
                   [&] { world_.dropThrough(id, s); });
            break;
        }
        case 15: {
            const std::uint32_t b = in_.bits();
            if (expect(live, "setCategory", [&] { world_.setCategory(id, b); }) &&
                world_.category(id) != b)
                finding("setCategory did not take");
            break;
        }
        case 16: {
            const std::uint32_t b = in_.bits();
            if (expect(live, "setMask", [&] { world_.setMask(id, b); }) && world_.mask(id) != b)
                finding("setMask did not take");
            break;
        }
        case 17: {
            const bool s = in_.byte() > 220;
            if (expect(live, "setSensor", [&] { world_.setSensor(id, s); }) &&
                world_.isSensor(id) != s)
                finding("setSensor did not take");
            break;
        }
        case 18:
            // Teleport far away and back: the grids must follow.
            if (live) {
                const Vec2 p = world_.position(id);
                // Towards the origin: never beyond the edge of the world (math.hpp).
                world_.setPosition(id, {p.x > 0 ? p.x - 5000 : p.x + 5000, p.y});
                world_.setPosition(id, p);
            }
            break;
        }
        checkList("a setter");
    }

    /// Every getter of a body: a stale handle throws from each, a live one answers.
    void readBody() {
        const BodyId id = pickBody();
        const bool live = isLive(id);
        if (world_.isValid(id) != live)
            finding("isValid(" + check::describe(id) + ") disagrees with the fuzzer's list");
        expect(live, "getters", [&] {
            (void)world_.bodyDef(id);
            (void)world_.type(id);
            (void)world_.isAwake(id);
            (void)world_.touching(id);
            (void)world_.separation(id);
            (void)world_.mass(id);
            (void)tileMapOf(world_, id);
        });
    }

    /// Characters, forces, contacts now and move(), with their rules from world.hpp and
    /// query.hpp.
    void characterOp() {
        const BodyId id = pickBody();
        const bool live = isLive(id);
        tamper(id);
        const int which = in_.byte() % (ramps_ ? 10 : 8);
        if (verbosity() >= 1)
            std::fprintf(stderr, "character op %d on %s\n", which, check::describe(id).c_str());
        switch (which) {
        case 0: {
            const bool c = in_.flag();
            if (expect(live, "setCharacter", [&] { world_.setCharacter(id, c); }) &&
                world_.isCharacter(id) != c)
                finding("setCharacter did not take");
            break;
        }
        case 1: {
            const float s = in_.number(-400, 400);
            // Only a character walks (world.hpp).
            const bool walker =
                live && world_.isCharacter(id) && world_.type(id) == BodyType::Dynamic;
            if (expect(walker && inRange(s), "setWalkSpeed", [&] { world_.setWalkSpeed(id, s); }) &&
                !same(world_.walkSpeed(id), s))
                finding("setWalkSpeed did not take");
            break;
        }
        case 2: {
            const float f = in_.number(0, 1);
            if (expect(live && f >= 0 && f <= 1, "setWallFriction",
                       [&] { world_.setWallFriction(id, f); }) &&
                !same(world_.wallFriction(id), f))
                finding("setWallFriction did not take");
            break;
        }
        case 3: {
            const Vec2 f = in_.vec(-1e5f, 1e5f);
            expect(live && inRange(f), "applyForce", [&] { world_.applyForce(id, f); });
            break;
        }
        case 4: {
            const Vec2 j = in_.vec(-1e4f, 1e4f);
            expect(live && inRange(j), "applyImpulse", [&] { world_.applyImpulse(id, j); });
            break;
        }
        case 5:
            expect(live, "contacts now", [&] {
                for (const ContactInfo& c : world_.contacts(id)) {
                    if (!world_.isValid(c.other) || !world_.isTouching(id, c.other))
                        finding("contacts listed a body isTouching denies");
                }
                if (const std::optional<Ground> g = world_.ground(id);
                    g && !world_.isValid(g->body))
                    finding("ground named a destroyed body");
            });
            break;
        case 6: {
            const Vec2 d = in_.vec(-300, 300);
            const bool ok = live && inRange(d) && inRange(world_.position(id) + d);
            const std::uint8_t responses = in_.byte();
            if (verbosity() >= 1 && live)
                std::fprintf(stderr, "move: from %s by %s, responses %d\n",
                             check::describe(world_.position(id)).c_str(),
                             check::describe(d).c_str(), responses);
            expect(ok, "move", [&] {
                const MoveOutcome out = move(world_, id, d, [&](BodyId other) {
                    return static_cast<Response>((responses + other.index) % 5);
                });
                if (!same(world_.position(id), out.centre))
                    finding("move left the body elsewhere than it said");
            });
            break;
        }
        case 8: {
            const float a = in_.number(0, 90);
            if (expect(live && a >= 0 && a < 90, "setFloorAngle",
                       [&] { world_.setFloorAngle(id, a); }) &&
                !same(world_.floorAngle(id), a))
                finding("setFloorAngle did not take");
            break;
        }
        case 9: {
            const float d = in_.number(0, 40);
            if (expect(live && inRange(d) && d >= 0, "setSnapDown",
                       [&] { world_.setSnapDown(id, d); }) &&
                !same(world_.snapDown(id), d))
                finding("setSnapDown did not take");
            break;
        }
        default: {
            std::vector<Vec2> positions(live_.size() + 1);
            if (world_.readPositions(positions) != world_.bodyCount())
                finding("readPositions did not read every body");
            break;
        }
        }
        checkList("a character operation");
    }

    // --- Stepping --------------------------------------------------------------------------

    float pickDt() {
        switch (in_.byte() % 8) {
        case 0:
        case 1:
        case 2:
        case 3:
            return 1.0f / 60.0f;
        case 4:
            return 1.0f / 30.0f;
        case 5:
            return 1.0f / 120.0f;
        case 6:
            return in_.number(1e-4f, 0.1f);
        default:
            return in_.special();
        }
    }

    void step() {
        const float dt = pickDt();
        // Now and then long enough for bodies at rest to fall asleep (kTimeToSleep).
        const std::uint8_t steps = in_.byte();
        const int count = characters_ && steps >= 248 ? 45 : 1 + steps % 8;
        const bool valid = isSize(dt); // finite, > 0, and in math.hpp's range
        for (int i = 0; i < count; ++i) {
            if (verbosity() >= 2)
                dump(dt);
            const std::vector<std::uint32_t> before =
                valid ? std::vector<std::uint32_t>{} : snapshot();
            callbackCalls_ = 0;
            inStep_ = true;
            bool thrown = false;
            try {
                // JOSTLE_FUZZ_VERBOSE=3: trap the first invalid operation (a NaN made) in
                // the step, to see where it is made.
                if (verbosity() >= 3)
                    feenableexcept(FE_INVALID | FE_OVERFLOW | FE_DIVBYZERO);
                world_.step(dt);
                if (verbosity() >= 3)
                    fedisableexcept(FE_INVALID | FE_OVERFLOW | FE_DIVBYZERO);
            } catch (const Error& error) {
                inStep_ = false;
                if (valid)
                    finding(std::string("step(") + std::to_string(dt) +
                            ") refused: " + error.what());
                requireUnchanged(before, "step");
                return;
            } catch (const CallbackThrow&) {
                thrown = true; // the world must still be whole and steppable
                if (verbosity() >= 2)
                    std::fprintf(stderr, "  (the callback threw)\n");
            }
            inStep_ = false;
            if (!valid)
                finding("step accepted dt " + std::to_string(dt));
            ++steps_;
            checkWorld("step", !thrown);
        }
    }

    /// The world before a step, for JOSTLE_FUZZ_VERBOSE=2.
    void dump(float dt) const {
        std::fprintf(stderr, "step(%.9g): gravity %s, maxVelocity %.9g, %s, sleeping %d\n",
                     static_cast<double>(dt), check::describe(world_.gravity()).c_str(),
                     static_cast<double>(world_.maxVelocity()), toString(world_.solver()),
                     world_.sleeping());
        for (BodyId id : live_)
            std::fprintf(stderr, "  %s %s at %s half %s v %s mass %.9g%s\n",
                         check::describe(id).c_str(), toString(world_.type(id)),
                         check::describe(world_.position(id)).c_str(),
                         check::describe(world_.halfExtents(id)).c_str(),
                         check::describe(world_.velocity(id)).c_str(),
                         static_cast<double>(world_.mass(id)), world_.isAwake(id) ? "" : " asleep");
    }

    // --- Invariants ----------------------------------------------------------------------

    void checkList(const char* after) {
        const std::span<const BodyId> listed = world_.bodies();
        if (!std::equal(listed.begin(), listed.end(), live_.begin(), live_.end()))
            finding(std::string(after) + ": bodies() differs from the fuzzer's list");
        if (world_.bodyCount() != live_.size())
            finding(std::string(after) + ": bodyCount differs");
    }

    void checkWorld(const char* after, bool stepCompleted) {
        checkList(after);
        for (BodyId id : dead_) {
            if (world_.isValid(id))
                finding(check::describe(id) + " is valid after being destroyed");
            try {
                (void)world_.position(id);
                finding("position() of a destroyed body did not throw");
            } catch (const Error&) {
            }
        }
        if (auto problem = check::finiteState(world_))
            finding(std::string("after ") + after + ": " + *problem);
        for (BodyId id : live_) {
            if (world_.type(id) != BodyType::Dynamic && !world_.isAwake(id))
                finding("a static or kinematic body is asleep");
            if (world_.solver() == Solver::Classic && !world_.isAwake(id))
                finding("a body sleeps in the classic model");
        }
        for (const Map& m : maps_) {
            if (!world_.isValid(m.id))
                finding("a live tile map became invalid");
            if (tileMapDef(world_, m.id).rows != m.rows)
                finding("a tile map's tiles changed by themselves");
            for (BodyId body : tileMapBodies(world_, m.id)) {
                // A body of the map that the program destroyed is forgotten, not reused.
                if (world_.isValid(body) && (tileMapOf(world_, body) != m.id || !isLive(body)))
                    finding("tileMapBodies lists a body that tileMapOf or bodies() disown");
            }
        }
        for (TileMapId map : deadMaps_)
            if (world_.isValid(map))
                finding("a destroyed tile map is valid");
        if (!stepCompleted)
            return;
        for (const ContactEvent& e : world_.contactBegins()) {
            if (!world_.isValid(e.a) || !world_.isValid(e.b))
                finding("contactBegins names " + check::describe(e.a) +
                        (world_.isValid(e.a) ? "" : " (gone)") + " and " + check::describe(e.b) +
                        (world_.isValid(e.b) ? "" : " (gone)") + " in the " +
                        toString(world_.solver()) + " model, callback mode " +
                        std::to_string(callbackMode_));
            if (!goodNormal(e.normal, e.a, e.b) || !(e.approachSpeed >= 0) ||
                !std::isfinite(e.approachSpeed))
                finding("contactBegins: bad normal or approach speed");
        }
        for (const ContactEvent& e : world_.contactEnds())
            if (!goodNormal(e.normal, e.a, e.b))
                finding("contactEnds: bad normal");
        for (const CrushEvent& e : world_.crushBegins())
            if (!world_.isValid(e.body) || !world_.isValid(e.by) || !world_.isValid(e.against))
                finding("crushBegins names a body that is gone");
    }

    // --- Queries -----------------------------------------------------------------------

    QueryFilter pickFilter() {
        QueryFilter filter;
        const std::uint8_t b = in_.byte();
        if (b & 1)
            filter.mask = in_.bits() & 0xF;
        if (b & 2)
            filter.category = in_.bits() & 0xF;
        filter.includeSensors = (b & 4) != 0;
        if (b & 8)
            filter.ignore = pickBody();
        return filter;
    }

    /// A place near a body, most of the time, so that queries find something.
    Vec2 pickPoint() {
        if (!live_.empty() && in_.byte() < 160) {
            const BodyId id = live_[in_.byte() % live_.size()];
            return world_.position(id) + in_.vec(-30, 30);
        }
        return in_.vec(-500, 500);
    }

    bool passes(BodyId id, const QueryFilter& filter) const {
        return (world_.category(id) & filter.mask) != 0 &&
               (filter.category & world_.mask(id)) != 0 &&
               (filter.includeSensors || !world_.isSensor(id)) && id != filter.ignore;
    }

    std::size_t rank(BodyId id) const {
        return static_cast<std::size_t>(std::find(live_.begin(), live_.end(), id) - live_.begin());
    }

    /// What a "what is here?" query must do with a body.
    enum class Must { Report, Leave, Either };

    /// The part of a query's region nearest the solid side of a ramp's slope, within the
    /// ramp's box: its point nearest that side, how far the part reaches into the box from
    /// the box's edges (0 for a point on an edge), and the largest coordinate the query
    /// works with.
    struct Reach {
        Vec2 point;
        float depth;
        float scale;
    };

    /// What a "what is here?" query must do with each body whose box `inBox(lo, hi)` puts
    /// in the region, by brute force over the fuzzer's list, in creation order. A sharp box
    /// is reported: the grids of the library must agree with it exactly. A ramp is
    /// reported if the region reaches the solid side of its slope (`reach(lo, hi, slope)`)
    /// and left out if it does not, unless the slope or the box's edge is within rounding
    /// of the region, where the library's float arithmetic may go either way.
    template <class InBox, class ReachOf>
    std::vector<std::pair<BodyId, Must>> bruteForce(const QueryFilter& filter, InBox&& inBox,
                                                    ReachOf&& reach) const {
        std::vector<std::pair<BodyId, Must>> out;
        for (BodyId id : live_) {
            const Vec2 p = world_.position(id), h = world_.halfExtents(id);
            if (!inBox(p - h, p + h) || !passes(id, filter))
                continue;
            if (!isShaped(id)) {
                out.emplace_back(id, Must::Report);
                continue;
            }
            const Vec2 slope = world_.bodyDef(id).slope;
            if (slope == Vec2{}) { // a rounded body: made only in the way of a fast one
                out.emplace_back(id, Must::Either);
                continue;
            }
            const Reach r = reach(p - h, p + h, slope);
            const double scale =
                static_cast<double>(std::max({r.scale, std::abs(p.x) + h.x, std::abs(p.y) + h.y}));
            // A few float roundings of the largest coordinate, in distance and along the
            // slope's side (in half extents).
            const double rounding =
                64.0 * static_cast<double>(std::numeric_limits<float>::epsilon()) * scale;
            const double blur =
                rounding * (1.0 / static_cast<double>(h.x) + 1.0 / static_cast<double>(h.y));
            const double side = slopeSide(p, h, slope, static_cast<double>(r.point.x),
                                          static_cast<double>(r.point.y));
            out.emplace_back(id, static_cast<double>(r.depth) <= rounding || std::abs(side) <= blur
                                     ? Must::Either
                                 : side < 0 ? Must::Report
                                            : Must::Leave);
        }
        return out;
    }

    /// True if `got` lists, in creation order, every body `expected` must report, and no
    /// body it must not.
    static bool agrees(const std::vector<BodyId>& got,
                       const std::vector<std::pair<BodyId, Must>>& expected) {
        std::size_t k = 0;
        for (const auto& [id, must] : expected) {
            const bool listed = k < got.size() && got[k] == id;
            if ((listed && must == Must::Leave) || (!listed && must == Must::Report))
                return false;
            k += listed ? 1 : 0;
        }
        return k == got.size();
    }

    void query() {
        const QueryFilter filter = pickFilter();
        const bool ignoreOk = filter.ignore.isNull() || isLive(filter.ignore);
        const std::uint8_t which = in_.byte() % 7;
        const Vec2 a = pickPoint();
        switch (which) {
        case 0: {
            std::vector<BodyId> got;
            if (!expect(ignoreOk && inRange(a), "queryPoint",
                        [&] { got = queryPoint(world_, a, filter); }))
                break;
            const auto expected = bruteForce(
                filter,
                [&](Vec2 lo, Vec2 hi) {
                    return lo.x <= a.x && a.x <= hi.x && lo.y <= a.y && a.y <= hi.y;
                },
                [&](Vec2 lo, Vec2 hi, Vec2) {
                    const float depth = std::min({a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y});
                    return Reach{a, depth, std::max(std::abs(a.x), std::abs(a.y))};
                });
            if (!agrees(got, expected))
                finding("queryPoint differs from brute force");
            break;
        }
        case 1:
        case 2: {
            const Vec2 half = in_.vec(0, 80);
            const bool box = which == 1;
            const Vec2 lo = box ? a - half : a, hi = box ? a + half : a + half * 2.0f;
            // queryBox: half >= 0 and corners that do not overflow; queryRect: min <= max.
            const bool ok = box ? inRange(a) && inRange(half) && half.x >= 0 && half.y >= 0 &&
                                      isFinite(lo) && isFinite(hi)
                                : inRange(lo) && inRange(hi) && lo.x <= hi.x && lo.y <= hi.y;
            std::vector<BodyId> got;
            if (!expect(ignoreOk && ok, box ? "queryBox" : "queryRect", [&] {
                    got =
                        box ? queryBox(world_, a, half, filter) : queryRect(world_, lo, hi, filter);
                }))
                break;
            const auto expected = bruteForce(
                filter,
                [&](Vec2 bl, Vec2 bh) {
                    return bl.x < hi.x && lo.x < bh.x && bl.y < hi.y && lo.y < bh.y;
                },
                [&](Vec2 bl, Vec2 bh, Vec2 slope) {
                    // Where the box and the ramp's box share area, the corner furthest
                    // towards the solid side, against the slope's corner.
                    const Vec2 from{std::max(lo.x, bl.x), std::max(lo.y, bl.y)};
                    const Vec2 to{std::min(hi.x, bh.x), std::min(hi.y, bh.y)};
                    const Vec2 corner{slope.x > 0 ? from.x : to.x, slope.y > 0 ? from.y : to.y};
                    return Reach{
                        corner, std::min(to.x - from.x, to.y - from.y),
                        std::max({std::abs(lo.x), std::abs(lo.y), std::abs(hi.x), std::abs(hi.y)})};
                });
            if (!agrees(got, expected))
                finding(std::string(box ? "queryBox" : "queryRect") + " differs from brute force");
            break;
        }
        case 3:
        case 4: {
            const Vec2 to = in_.flag() ? pickPoint() : a + in_.vec(-800, 800);
            const bool ok = ignoreOk && inRange(a) && inRange(to) && isFinite(to - a);
            std::optional<RayHit> first;
            std::vector<RayHit> all;
            if (!expect(ok, "rayCast", [&] {
                    first = rayCast(world_, a, to, filter);
                    all = rayCastAll(world_, a, to, filter);
                }))
                break;
            if (first.has_value() != !all.empty() ||
                (first && (first->body != all[0].body || !same(first->fraction, all[0].fraction))))
                finding("rayCast and rayCastAll disagree on the first hit");
            for (std::size_t i = 0; i < all.size(); ++i) {
                const RayHit& hit = all[i];
                if (!isLive(hit.body) || !passes(hit.body, filter) ||
                    !goodNormal(hit.normal, hit.body) || !isFinite(hit.point) ||
                    !(hit.fraction >= 0 && hit.fraction <= 1))
                    finding("rayCastAll: a bad hit");
                if (i > 0 && (hit.fraction < all[i - 1].fraction ||
                              (hit.fraction == all[i - 1].fraction &&
                               rank(hit.body) <= rank(all[i - 1].body))))
                    finding("rayCastAll: hits out of order or repeated");
            }
            break;
        }
        case 5:
        case 6: {
            const Vec2 half = in_.vec(0.25f, 40);
            const Vec2 move = in_.vec(-300, 300);
            const bool ok = ignoreOk && inRange(a) && inRange(half) && half.x > 0 && half.y > 0 &&
                            isFinite(a - half) && isFinite(a + half) && inRange(move) &&
                            isFinite(a + move);
            if (which == 5) {
                std::optional<BoxCastHit> hit;
                if (expect(ok, "boxCast", [&] { hit = boxCast(world_, a, half, move, filter); }) &&
                    hit &&
                    (!isLive(hit->body) || !passes(hit->body, filter) ||
                     !goodNormal(hit->normal, hit->body) || !isFinite(hit->centre) ||
                     !(hit->fraction >= 0 && hit->fraction <= 1)))
                    finding("boxCast: a bad hit");
            } else {
                MoveResult moved;
                if (expect(ok, "moveAndSlide",
                           [&] { moved = moveAndSlide(world_, a, half, move, filter); })) {
                    if (!isFinite(moved.centre))
                        finding("moveAndSlide: centre not finite");
                    for (const MoveHit& hit : moved.hits)
                        if (!isLive(hit.body) || world_.isSensor(hit.body) ||
                            !goodNormal(hit.normal, hit.body))
                            finding("moveAndSlide: a bad hit");
                }
            }
            break;
        }
        }
    }

    // --- Tile maps -----------------------------------------------------------------------

    TileMapDef makeTileMapDef() {
        TileMapDef d;
        d.x = in_.number(-300, 300);
        d.y = in_.number(-300, 300);
        d.tile = in_.number(2, 40);
        const int rows = 1 + in_.byte() % 6, columns = 1 + in_.byte() % 10;
        for (int r = 0; r < rows; ++r) {
            std::string row;
            const std::uint32_t solid = in_.bits();
            for (int c = 0; c < columns; ++c)
                row += (solid >> c) & 1 ? '#' : '.';
            if (ramps_)
                placeRamps(row);
            d.rows.push_back(row);
        }
        const std::uint8_t odd = in_.byte();
        if (odd == 255)
            d.rows.back().pop_back(); // ragged, or an empty row
        else if (odd == 254)
            d.rows.back().back() = 'x';
        else if (odd == 253)
            d.rows.clear();
        const std::uint8_t extras = in_.byte();
        if (extras & 1) {
            d.friction = in_.number(0, 1);
            d.bounce = in_.number(0, 1);
        }
        if (extras & 2)
            d.oneWay = pickOneWay();
        d.sensor = (extras & 12) == 12;
        if (extras & 16) {
            d.category = 1u << (in_.byte() % 4);
            d.mask = in_.bits() & 0xF;
        }
        return d;
    }

    /// Ramps over some of a row's tiles, the two halves of a 2:1 ramp side by side often.
    void placeRamps(std::string& row) {
        static constexpr std::array<std::string_view, 16> pieces = {
            "/", "\\", "7", "F", "r", "R", "L", "l", "c", "C", "D", "d", "rR", "Ll", "cC", "Dd"};
        const std::uint32_t where = in_.bits();
        for (std::size_t c = 0; c < row.size(); ++c)
            if ((where >> c) & 1) {
                const std::string_view piece = pieces[in_.byte() % pieces.size()];
                for (std::size_t k = 0; k < piece.size() && c + k < row.size(); ++k)
                    row[c + k] = piece[k];
            }
    }

    /// A tile's character for setTile: mostly one that rows may hold, sometimes any byte.
    char pickTile() {
        static constexpr std::string_view tiles = "#./\\7FrRLlcCDd";
        const std::uint8_t b = in_.byte();
        return b < 240 ? tiles[b % tiles.size()] : static_cast<char>(in_.byte());
    }

    void tileMapOp() {
        switch (in_.byte() % (ramps_ ? 7 : 5)) {
        case 0: {
            TileMapDef d = makeTileMapDef();
            if (maps_.size() >= kMaxMaps || live_.size() >= kMaxBodies)
                return;
            const bool documented = inRange(d.x) && inRange(d.y) && inRange(d.tile) &&
                                    d.tile / 2 >= kMinMagnitude && inRange(d.friction) &&
                                    inRange(d.bounce) && !d.rows.empty() && !d.rows[0].empty() &&
                                    isValidOneWay(d.oneWay);
            const bool checked = !checkTileMapDef(d).has_value();
            if (checked && !documented)
                finding("checkTileMapDef accepted an invalid TileMapDef");
            if (verbosity() >= 1) {
                std::fprintf(stderr, "createTileMap: x %.9g, y %.9g, tile %.9g, %zu x %zu\n",
                             static_cast<double>(d.x), static_cast<double>(d.y),
                             static_cast<double>(d.tile), d.rows.empty() ? 0 : d.rows[0].size(),
                             d.rows.size());
                for (const std::string& row : d.rows)
                    std::fprintf(stderr, "  %s\n", row.c_str());
            }
            // The classic model has sharp boxes only: a map with a ramp is refused whole.
            const bool valid = checked && !(world_.solver() == Solver::Classic && hasRamp(d.rows));
            TileMapId id;
            if (!expect(valid, "createTileMap", [&] { id = createTileMap(world_, d); }))
                return;
            maps_.push_back({id, d.rows});
            catchUp("createTileMap", {});
            checkNewMap(id, d);
            break;
        }
        case 1: {
            const TileMapId id = pickMap();
            Map* m = findMap(id);
            const int columns = m ? static_cast<int>(m->rows[0].size()) : 4;
            const int rows = m ? static_cast<int>(m->rows.size()) : 4;
            const int column = in_.integer(-1, columns), row = in_.integer(-1, rows);
            const bool solid = in_.flag();
            const bool ok = m && column >= 0 && column < columns && row >= 0 && row < rows;
            const std::vector<BodyId> before =
                m ? std::vector<BodyId>(tileMapBodies(world_, id).begin(),
                                        tileMapBodies(world_, id).end())
                  : std::vector<BodyId>{};
            if (!expect(ok, "setTile", [&] { setTile(world_, id, column, row, solid); }))
                return;
            m->rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] =
                solid ? '#' : '.';
            catchUp("setTile", before);
            if (isSolid(world_, id, column, row) != solid)
                finding("setTile did not take");
            checkCoverage(*m);
            break;
        }
        case 2: {
            const TileMapId id = pickMap();
            Map* m = findMap(id);
            const std::vector<BodyId> before =
                m ? std::vector<BodyId>(tileMapBodies(world_, id).begin(),
                                        tileMapBodies(world_, id).end())
                  : std::vector<BodyId>{};
            if (!expect(m != nullptr, "destroyTileMap", [&] { destroyTileMap(world_, id); }))
                return;
            maps_.erase(maps_.begin() + (m - maps_.data()));
            deadMaps_.push_back(id);
            catchUp("destroyTileMap", before);
            for (BodyId body : before)
                if (world_.isValid(body))
                    finding("destroyTileMap left one of its bodies");
            break;
        }
        case 3: {
            const TileMapId id = pickMap();
            Map* m = findMap(id);
            const int column = in_.integer(-3, 12), row = in_.integer(-3, 8);
            const Vec2 p = in_.vec(-400, 400);
            expect(m != nullptr, "isSolid", [&] {
                const bool solid = isSolid(world_, id, column, row);
                const bool inside = column >= 0 && row >= 0 &&
                                    row < static_cast<int>(m->rows.size()) &&
                                    column < static_cast<int>(m->rows[0].size());
                const bool expected =
                    inside &&
                    m->rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] == '#';
                if (solid != expected)
                    finding("isSolid disagrees with the tiles set");
            });
            std::optional<TileCoord> at;
            if (expect(m != nullptr && inRange(p), "tileAt", [&] { at = tileAt(world_, id, p); }) &&
                at &&
                (at->column < 0 || at->row < 0 || at->column >= tileMapColumns(world_, id) ||
                 at->row >= tileMapRows(world_, id)))
                finding("tileAt outside the map");
            break;
        }
        case 4: {
            // The program destroys one of a map's bodies itself: allowed, and forgotten.
            if (maps_.empty())
                return;
            const Map& m = maps_[in_.byte() % maps_.size()];
            const std::span<const BodyId> bodies = tileMapBodies(world_, m.id);
            if (bodies.empty())
                return;
            const BodyId body = bodies[in_.byte() % bodies.size()];
            if (!world_.isValid(body))
                return;
            tamper(body);
            world_.destroyBody(body);
            buried(body);
            checkList("destroying a tile map's body");
            break;
        }
        case 5: {
            // Any character: '#', '.' and the ramps are tiles, but a ramp in the classic
            // model; tileOf gives back what was set.
            const TileMapId id = pickMap();
            Map* m = findMap(id);
            const int columns = m ? static_cast<int>(m->rows[0].size()) : 4;
            const int rows = m ? static_cast<int>(m->rows.size()) : 4;
            const int column = in_.integer(-1, columns), row = in_.integer(-1, rows);
            const char tile = pickTile();
            const bool inside = m && column >= 0 && column < columns && row >= 0 && row < rows;
            // A ramp where createTileMap would refuse it is refused: in the classic model, in
            // a one-way map, a 2:1 half in a map of tiles too small for it.
            bool rampRefused = false;
            if (inside && isRampChar(tile)) {
                TileMapDef placed = tileMapDef(world_, id);
                placed.rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = tile;
                rampRefused = world_.solver() == Solver::Classic || checkTileMapDef(placed);
            }
            const bool ok = inside && isTileChar(tile) && !rampRefused;
            if (verbosity() >= 1)
                std::fprintf(stderr, "setTile: (%d, %d) to byte 0x%02X\n", column, row,
                             static_cast<unsigned>(static_cast<unsigned char>(tile)));
            const std::vector<BodyId> before =
                m ? std::vector<BodyId>(tileMapBodies(world_, id).begin(),
                                        tileMapBodies(world_, id).end())
                  : std::vector<BodyId>{};
            if (!expect(ok, "setTile(char)", [&] { setTile(world_, id, column, row, tile); }))
                return;
            m->rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = tile;
            catchUp("setTile(char)", before);
            if (tileOf(world_, id, column, row) != tile)
                finding("tileOf does not give back what setTile set");
            if (isSolid(world_, id, column, row) != (tile == '#'))
                finding("isSolid after setTile(char) is not whether it set '#'");
            checkCoverage(*m);
            break;
        }
        case 6: {
            // tileOf: the tile as set, '.' outside the map; a stale map throws.
            const TileMapId id = pickMap();
            Map* m = findMap(id);
            const int column = in_.integer(-3, 12), row = in_.integer(-3, 8);
            expect(m != nullptr, "tileOf", [&] {
                const char got = tileOf(world_, id, column, row); // throws for a stale map
                const bool inside = column >= 0 && row >= 0 &&
                                    row < static_cast<int>(m->rows.size()) &&
                                    column < static_cast<int>(m->rows[0].size());
                const char expected =
                    inside
                        ? m->rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)]
                        : '.';
                if (got != expected)
                    finding("tileOf disagrees with the tiles set");
            });
            break;
        }
        }
    }

    /// A new map's bodies come last in bodies(), in the order tileMapBodies lists them.
    void checkNewMap(TileMapId id, const TileMapDef& d) {
        const std::span<const BodyId> bodies = tileMapBodies(world_, id);
        if (bodies.size() > live_.size() ||
            !std::equal(bodies.begin(), bodies.end(),
                        live_.end() - static_cast<std::ptrdiff_t>(bodies.size())))
            finding("createTileMap: its bodies are not the last ones created, in order");
        if (tileMapColumns(world_, id) != static_cast<int>(d.rows[0].size()) ||
            tileMapRows(world_, id) != static_cast<int>(d.rows.size()))
            finding("createTileMap: wrong size");
        checkCoverage(*findMap(id));
    }

    /// Every solid tile's centre is inside exactly one body of the map, every empty one's
    /// in none, where floats can tell tiles apart and the program left the bodies alone. A
    /// ramp tile's centre may lie on its slope; a tenth of a tile from its top and from its
    /// bottom, one point is in its solid part, in one body, and the other in the part cut
    /// away, in none: the bottom one solid for a floor (tilemap.hpp draws a y-down world),
    /// the top one for a ceiling.
    void checkCoverage(const Map& m) {
        const TileMapDef d = tileMapDef(world_, m.id);
        if (d.rows != m.rows)
            finding("tileMapDef does not give back the tiles set");
        if (std::find(tampered_.begin(), tampered_.end(), m.id) != tampered_.end() ||
            !(std::abs(d.x) < 1e4f && std::abs(d.y) < 1e4f && d.tile > 0.01f))
            return;
        const bool parts = d.tile > 0.1f; // a tenth of a tile, well above rounding
        struct Piece {
            Vec2 centre, half, slope;
        };
        std::vector<Piece> pieces;
        for (BodyId body : tileMapBodies(world_, m.id)) {
            if (!world_.isValid(body) || world_.type(body) != BodyType::Static)
                finding("an untouched tile map lists a body that is gone or moves");
            pieces.push_back(
                {world_.position(body), world_.halfExtents(body), world_.bodyDef(body).slope});
        }
        // How many of the map's bodies hold the point (column + u, row + v), in tiles.
        auto holders = [&](std::size_t column, std::size_t row, double u, double v) {
            const double tile = static_cast<double>(d.tile);
            const double x = static_cast<double>(d.x) + (static_cast<double>(column) + u) * tile;
            const double y = static_cast<double>(d.y) + (static_cast<double>(row) + v) * tile;
            int count = 0;
            for (const Piece& piece : pieces) {
                const bool inBox = std::abs(x - static_cast<double>(piece.centre.x)) <
                                       static_cast<double>(piece.half.x) &&
                                   std::abs(y - static_cast<double>(piece.centre.y)) <
                                       static_cast<double>(piece.half.y);
                count += inBox && (piece.slope == Vec2{} ||
                                   slopeSide(piece.centre, piece.half, piece.slope, x, y) < 0);
            }
            return count;
        };
        for (std::size_t r = 0; r < d.rows.size(); ++r) {
            for (std::size_t c = 0; c < d.rows[r].size(); ++c) {
                const char tile = d.rows[r][c];
                const std::string where =
                    "tile (" + std::to_string(c) + ", " + std::to_string(r) + ") '" + tile + "'";
                if (!isRampChar(tile)) {
                    const int inside = holders(c, r, 0.5, 0.5);
                    if (inside != (tile == '#' ? 1 : 0))
                        finding(where + " is covered by " + std::to_string(inside) + " bodies");
                } else if (parts) {
                    const bool floor = kFloorRamps.find(tile) != std::string_view::npos;
                    const int top = holders(c, r, 0.5, 0.1), bottom = holders(c, r, 0.5, 0.9);
                    if (top != (floor ? 0 : 1) || bottom != (floor ? 1 : 0))
                        finding(where + ": its top is in " + std::to_string(top) +
                                " bodies, its bottom in " + std::to_string(bottom));
                }
            }
        }
    }

    // --- The world's settings -------------------------------------------------------------

    void worldSetting() {
        switch (in_.byte() % 6) {
        case 0: {
            const Vec2 g = in_.vec(-1000, 1000);
            if (expect(inRange(g), "setGravity", [&] { world_.setGravity(g); }) &&
                !same(world_.gravity(), g))
                finding("setGravity did not take");
            break;
        }
        case 1: {
            const float m = in_.byte() < 128 ? kInf : in_.number(1, 2000);
            expect(!std::isnan(m) && m > 0, "setMaxVelocity", [&] { world_.setMaxVelocity(m); });
            break;
        }
        case 2: {
            const auto s = static_cast<Solver>(in_.byte() % 3);
            // The classic model has sharp boxes only: not while the world has a shape, nor
            // while a map has ramp tiles (even with its ramp bodies destroyed).
            const bool rampTiles = std::any_of(maps_.begin(), maps_.end(),
                                               [](const Map& m) { return hasRamp(m.rows); });
            expect(s == Solver::Physical || (s == Solver::Classic && !anyShaped() && !rampTiles),
                   "setSolver", [&] { world_.setSolver(s); });
            break;
        }
        case 3: {
            const bool on = in_.flag();
            world_.setSleeping(on);
            if (!on)
                for (BodyId id : live_)
                    if (!world_.isAwake(id))
                        finding("setSleeping(false) left a body asleep");
            break;
        }
        case 4:
            world_.setClassicOptions({in_.flag(), in_.flag(), in_.flag()});
            break;
        case 5: {
            PhysicalOptions p;
            p.velocityIterations = in_.integer(0, 10);
            p.positionIterations = in_.integer(-1, 6);
            p.slop = in_.number(0, 0.5f);
            p.correction = in_.number(0, 1);
            p.restitutionThreshold = in_.number(0, 100);
            p.frictionMix = static_cast<FrictionMix>(in_.byte() % 3);
            WorldDef d;
            d.physical = p;
            expect(documentedValid(d), "setPhysicalOptions", [&] { world_.setPhysicalOptions(p); });
            break;
        }
        }
    }

    // --- Pre-solve callbacks ----------------------------------------------------------------

    void installCallback() {
        // Modes 12 and 13 came with issue 28, in the mix of characters and move().
        callbackMode_ = in_.byte() % (characters_ ? 14 : 12);
        callbackParam_ = in_.byte();
        if (verbosity() >= 1)
            std::fprintf(stderr, "callback: mode %d, parameter %d\n", callbackMode_,
                         callbackParam_);
        if (callbackMode_ == 0) {
            world_.setPreSolve({});
            return;
        }
        world_.setPreSolve([this](Collision& c) { return preSolve(c); });
    }

    bool preSolve(Collision& c) {
        if (!inStep_)
            finding("pre-solve called outside step()");
        ++callbackCalls_;
        if (!world_.isValid(c.a) || !world_.isValid(c.b) || c.a == c.b)
            finding("pre-solve given " + check::describe(c.a) +
                    (world_.isValid(c.a) ? "" : " (gone)") + " and " + check::describe(c.b) +
                    (world_.isValid(c.b) ? "" : " (gone)") + " in the " +
                    toString(world_.solver()) + " model, callback mode " +
                    std::to_string(callbackMode_) + ", call " + std::to_string(callbackCalls_));
        if (!goodNormal(c.normal, c.a, c.b) || !std::isfinite(c.depth) ||
            !(c.bounce >= 0 && c.bounce <= 1) || !(c.friction >= 0 && c.friction <= 1))
            finding("pre-solve given a bad Collision: normal " + check::describe(c.normal) +
                    (isShaped(c.a) || isShaped(c.b) ? " (a shape)" : "") + ", depth " +
                    std::to_string(c.depth) + ", bounce " + std::to_string(c.bounce) +
                    ", friction " + std::to_string(c.friction));
        checkList("pre-solve");
        // Every few calls, do what the mode says.
        const int every = 1 + callbackParam_ % 4;
        if (callbackCalls_ % every != 0)
            return true;
        switch (callbackMode_) {
        case 1:
            return (c.a.index + c.b.index + callbackParam_) % 2 == 0; // veto some pairs
        case 2:
            c.bounce = static_cast<float>(callbackParam_ % 5) / 4.0f;
            c.friction = static_cast<float>(callbackParam_ % 3) / 2.0f;
            return true;
        case 3: {
            // Destroy one of the pair: it leaves the rest of the step.
            const BodyId victim = callbackParam_ & 1 ? c.a : c.b;
            tamper(victim);
            world_.destroyBody(victim);
            buried(victim);
            return true;
        }
        case 4: {
            // Create a body of any type: clear above the pair, or right where one of it is
            // (in the way of bodies the step has yet to resolve); and destroy another.
            if (live_.size() >= kMaxBodies || callbackCalls_ > 8)
                return true;
            const int choice = (callbackParam_ >> 2) + callbackCalls_;
            const BodyType type = std::array{BodyType::Dynamic, BodyType::Static,
                                             BodyType::Kinematic}[std::size_t(choice % 3)];
            const Vec2 p = world_.position(choice & 4 ? c.b : c.a);
            const float lift = choice & 8 ? 0.0f : 20.0f;
            if (!inRange(p.y - lift))
                return true;
            const bool moves = type != BodyType::Static;
            const BodyId id = world_.createBody({.type = type,
                                                 .x = p.x,
                                                 .y = p.y - lift,
                                                 .hw = 2,
                                                 .hh = 2,
                                                 .vy = moves ? 10.0f : 0.0f,
                                                 .bounce = 0.5f});
            live_.push_back(id);
            if (choice & 16 && live_.size() > 1) {
                const BodyId victim = live_[std::size_t(choice) % (live_.size() - 1)];
                tamper(victim);
                world_.destroyBody(victim);
                buried(victim);
            }
            return true;
        }
        case 5:
            try {
                world_.step(1.0f / 60.0f);
                finding("step() from a callback did not throw");
            } catch (const Error&) {
            }
            return true;
        case 6: {
            // Queries see the bodies where the step has got them to.
            const Vec2 p = world_.position(c.a);
            for (BodyId id : queryBox(world_, p, {10, 10}))
                if (!world_.isValid(id))
                    finding("a query from a callback found a body that is gone");
            if (inRange(p + Vec2{0, 50})) // not beyond the edge of the world (math.hpp)
                (void)rayCast(world_, p, p + Vec2{0, 50});
            return true;
        }
        case 7:
            throw CallbackThrow{};
        case 8: {
            // Move and change what the step is working on.
            tamper(c.a);
            tamper(c.b);
            if (inRange(world_.position(c.b) + Vec2{0, -1}))
                world_.setPosition(c.b, world_.position(c.b) + Vec2{0, -1});
            world_.setVelocity(c.a, world_.type(c.a) == BodyType::Static ? Vec2{} : Vec2{0, -50});
            // Halved, but not below the smallest size (math.hpp).
            if (const Vec2 h = world_.halfExtents(c.b) * 0.5f;
                h.x >= kMinMagnitude && h.y >= kMinMagnitude &&
                std::min(h.x, h.y) >= world_.bodyDef(c.b).radius)
                world_.setHalfExtents(c.b, h);
            return true;
        }
        case 9:
            // Stale handles must throw here too.
            for (BodyId id : dead_) {
                try {
                    world_.setPosition(id, {});
                    finding("a stale handle was accepted during step()");
                } catch (const Error&) {
                }
            }
            return true;
        case 10: {
            // Change a tile of a map the pair belongs to.
            const TileMapId map = tileMapOf(world_, c.b);
            Map* m = findMap(map);
            if (!m)
                return true;
            const std::vector<BodyId> before(tileMapBodies(world_, map).begin(),
                                             tileMapBodies(world_, map).end());
            const int column = callbackParam_ % static_cast<int>(m->rows[0].size());
            const int row = callbackParam_ % static_cast<int>(m->rows.size());
            setTile(world_, map, column, row, false);
            m->rows[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = '.';
            catchUp("setTile in a callback", before);
            return true;
        }
        case 11: {
            // The world's settings do not change mid-step (world.hpp): each setter throws.
            const std::vector<std::uint32_t> before = snapshot();
            auto refused = [&](const char* name, auto&& call) {
                try {
                    call();
                    finding(std::string(name) + " from a callback did not throw");
                } catch (const Error&) {
                }
            };
            refused("setGravity", [&] { world_.setGravity({0, 10}); });
            refused("setMaxVelocity", [&] { world_.setMaxVelocity(100); });
            refused("setSolver", [&] { world_.setSolver(Solver::Classic); });
            refused("setSleeping", [&] { world_.setSleeping(false); });
            refused("setClassicOptions", [&] { world_.setClassicOptions({}); });
            refused("setPhysicalOptions", [&] { world_.setPhysicalOptions({}); });
            refused("setPreSolve", [&] { world_.setPreSolve({}); });
            requireUnchanged(before, "a world setter from a callback");
            return true;
        }
        case 12:
            inTheWayOfTheFastest();
            return true;
        case 13:
            moveFromCallback(c);
            return true;
        }
        return true;
    }

    /// Issue 28: something made mid-step right in the path of the fastest dynamic body,
    /// which the sweep then meets: a static box, a circle, or a solid tile of a map.
    void inTheWayOfTheFastest() {
        if (live_.size() >= kMaxBodies || callbackCalls_ > 8)
            return;
        BodyId fastest;
        float speed = -1.0f;
        for (BodyId id : live_)
            if (world_.type(id) == BodyType::Dynamic && length(world_.velocity(id)) > speed) {
                speed = length(world_.velocity(id));
                fastest = id;
            }
        if (fastest.isNull() || !std::isfinite(speed))
            return;
        const Vec2 ahead = world_.position(fastest) + world_.velocity(fastest) * (1.0f / 120.0f);
        if (!inRange(ahead) || !inRange(ahead + Vec2{4, 4}) || !inRange(ahead - Vec2{4, 4}))
            return;
        const int kind = callbackParam_ % 3;
        if (kind == 2) {
            for (Map& m : maps_) {
                const std::optional<TileCoord> at = tileAt(world_, m.id, ahead);
                if (!at || !world_.isValid(m.id))
                    continue;
                const std::vector<BodyId> before(tileMapBodies(world_, m.id).begin(),
                                                 tileMapBodies(world_, m.id).end());
                setTile(world_, m.id, at->column, at->row, true);
                m.rows[std::size_t(at->row)][std::size_t(at->column)] = '#';
                catchUp("setTile in the way of a fast body", before);
                return;
            }
        }
        const bool round = kind == 1 && world_.solver() == Solver::Physical;
        live_.push_back(world_.createBody({.type = BodyType::Static,
                                           .x = ahead.x,
                                           .y = ahead.y,
                                           .hw = 4,
                                           .hh = 4,
                                           .radius = round ? 4.0f : 0.0f}));
        if (round)
            shaped_.insert(std::uint64_t(live_.back().index) << 32 | live_.back().generation);
    }

    /// Issue 28: move() called from the pre-solve, with a filter that tries to change the
    /// world: every such call throws, and the world is as it was but for the moved body.
    void moveFromCallback(Collision& c) {
        const Vec2 d{float(callbackParam_ % 7) - 3.0f, float(callbackParam_ % 5) - 2.0f};
        const Vec2 p = world_.position(c.a);
        const float reach = std::abs(d.x) + std::abs(d.y);
        if (!inRange(p + Vec2{reach, reach}) || !inRange(p - Vec2{reach, reach}))
            return;
        tamper(c.a);
        const std::size_t bodies = world_.bodyCount();
        int attempts = 0;
        auto refused = [&](const char* name, auto&& call) {
            ++attempts;
            try {
                call();
                finding(std::string(name) + " from move()'s filter did not throw");
            } catch (const Error&) {
            }
        };
        move(world_, c.a, d, [&](BodyId other) {
            switch ((other.index + callbackParam_) % 5) {
            case 0:
                refused("createBody", [&] { world_.createBody({.hw = 1, .hh = 1}); });
                break;
            case 1:
                refused("destroyBody", [&] { world_.destroyBody(other); });
                break;
            case 2:
                refused("setPosition", [&] { world_.setPosition(other, {}); });
                break;
            case 3:
                refused("move", [&] { move(world_, other, {1, 0}); });
                break;
            default:
                for (Map& m : maps_)
                    if (world_.isValid(m.id))
                        refused("setTile", [&] { setTile(world_, m.id, 0, 0, true); });
                break;
            }
            return Response::Slide;
        });
        if (world_.bodyCount() != bodies)
            finding("a refused call from move()'s filter changed the bodies (" +
                    std::to_string(attempts) + " attempts)");
    }
};

// --- Settled mode ------------------------------------------------------------------------

/// Boxes dropped on a floor, left alone until they rest: none may rest deeper in a
/// static body than the slop.
class Settled {
public:
    explicit Settled(Input& in) : in_(in) {}

    void run() {
        static constexpr std::array<float, 3> scales = {1.0f, 1.0f / 64.0f, 16.0f};
        s_ = scales[in_.byte() % scales.size()];
        down_ = in_.flag() ? 1.0f : -1.0f; // y-down (screen) or y-up world
        const float g = 800.0f * s_ * (0.5f + static_cast<float>(in_.byte() % 4) * 0.5f);
        const float dt = in_.flag() ? 1.0f / 60.0f : 1.0f / 30.0f;
        WorldDef def;
        def.gravity = {0, down_ * g};
        def.sleeping = in_.byte() % 4 != 0;
        World world(def);
        buildFloor(world);
        const std::uint8_t count = in_.byte();
        const int n = 1 + count % 16;
        // Half the scenes drop boxes clear of one another, half create them where they
        // fall, inside one another (see clearOf).
        const bool overlapping = (count / 16) % 2 != 0;
        std::vector<BodyId> boxes;
        for (int i = 0; i < n; ++i) {
            BodyDef d = boxDef();
            if (!overlapping)
                clearOf(world, boxes, d);
            boxes.push_back(world.createBody(d));
        }
        if (verbosity() >= 1)
            print(world, dt);

        last_.resize(boxes.size());
        restTime_.assign(boxes.size(), 0.0f);
        lastDepth_.assign(boxes.size(), kInf);
        deepTime_.assign(boxes.size(), 0.0f);
        for (std::size_t k = 0; k < boxes.size(); ++k)
            last_[k] = world.position(boxes[k]);
        // Long enough for piles of 16 to come to rest.
        const int steps = static_cast<int>(8.0f / dt);
        for (int i = 0; i < steps; ++i)
            stepAndCheck(world, boxes, dt, i);
        if (world.sleeping()) {
            // Woken, the bodies that fell asleep must settle within the slop too.
            world.setSleeping(false);
            for (int i = steps; i < steps + static_cast<int>(2.0f / dt); ++i)
                stepAndCheck(world, boxes, dt, i);
        }
    }

    void stepAndCheck(World& world, const std::vector<BodyId>& boxes, float dt, int i) {
        world.step(dt);
        if (auto problem = check::finiteState(world))
            finding("settled: " + *problem);
        // Settled: every box on the floor at rest for as long as falling asleep takes
        // (0.5 s), as docs/sleeping.md counts rest: slower than 0.05 half extents a second,
        // and moved no further than that in the step (position correction moves a body
        // without giving it speed). Every box, not each one: a box at rest at the bottom
        // of a pile is still pushed down while the pile above sorts itself out. Boxes that
        // fell off the floor's ends never rest.
        bool settled = true;
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const BodyId id = boxes[k];
            const Vec2 h = world.halfExtents(id), p = world.position(id);
            const float slow = kSleepSpeed * std::min(h.x, h.y);
            const bool still =
                length(world.velocity(id)) < slow && length(p - last_[k]) <= slow * dt;
            restTime_[k] = still ? restTime_[k] + dt : 0.0f;
            last_[k] = p;
            const bool fallen = -down_ * p.y < 0.0f;
            settled = settled && (fallen || restTime_[k] >= kTimeToSleep);
        }
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            const BodyId id = boxes[k];
            if (!world.isAwake(id)) {
                // An island falls asleep only within the slop (docs/sleeping.md), and
                // keeps still while it sleeps.
                if (auto p = check::deepInStatic(world, id))
                    fail(world, id, *p, i);
                continue;
            }
            // Settled and awake: deeper than the slop only while position correction is
            // still taking it out, a little less deep at every step, or for moments: a
            // resting pile of small boxes trembles by a few hundredths of the slop. A body
            // deeper all through the time rest is judged over (0.5 s), and not on its way
            // out, is deeper than the slop lets it be.
            const std::optional<check::Penetration> p = check::deepInStatic(world, id);
            deepTime_[k] = p ? deepTime_[k] + dt : 0.0f;
            if (settled && p && !(p->depth < lastDepth_[k]) && deepTime_[k] >= kTimeToSleep)
                fail(world, id, *p, i);
            lastDepth_[k] = p ? p->depth : kInf;
        }
    }

private:
    Input& in_;
    float s_ = 1;
    // Per box: where it was after the last step, how long it has rested, how deep beyond
    // the slop it sat in a static body (infinity: not beyond), and since when.
    std::vector<Vec2> last_;
    std::vector<float> restTime_;
    std::vector<float> lastDepth_;
    std::vector<float> deepTime_; ///< how long it has been deeper than the slop
    float down_ = 1;

    /// A point `height` above the floor's top (y = 0) in this world's "up".
    float above(float height) const { return -down_ * height; }

    // docs/sleeping.md: a body is at rest below this speed in half extents per second,
    // and an island falls asleep once all of it has rested this long.
    static constexpr float kSleepSpeed = 0.05f;
    static constexpr float kTimeToSleep = 0.5f;

    /// Moves the box `d` up until it overlaps none of `boxes`, so that the scene is boxes
    /// dropped on a floor. Boxes created inside one another are the harder test: the
    /// correction that pushes them apart is what used to squeeze bodies into static ones
    /// (tests/fuzz/open/README.md, squeezed-into-static).
    void clearOf(const World& world, const std::vector<BodyId>& boxes, BodyDef& d) const {
        for (bool moved = true; moved;) {
            moved = false;
            for (BodyId id : boxes) {
                const Vec2 p = world.position(id), h = world.halfExtents(id);
                if (std::abs(p.x - d.x) < h.x + d.hw && std::abs(p.y - d.y) < h.y + d.hh + s_) {
                    d.y = p.y + above(h.y + d.hh + s_);
                    moved = true;
                }
            }
        }
    }

    /// The scene as C++, to turn a finding into a unit test.
    static void print(const World& world, float dt) {
        std::fprintf(stderr, "// dt = %.9g, sleeping = %d\nWorldDef{.gravity = {%.9g, %.9g}}\n",
                     static_cast<double>(dt), world.sleeping(),
                     static_cast<double>(world.gravity().x),
                     static_cast<double>(world.gravity().y));
        for (BodyId id : world.bodies()) {
            const BodyDef d = world.bodyDef(id);
            std::fprintf(stderr,
                         "{.type = BodyType::%s, .x = %.9g, .y = %.9g, .hw = %.9g, .hh = %.9g, "
                         ".bounce = %.9g, .friction = %.9g, .density = %.9g}\n",
                         d.type == BodyType::Static ? "Static" : "Dynamic",
                         static_cast<double>(d.x), static_cast<double>(d.y),
                         static_cast<double>(d.hw), static_cast<double>(d.hh),
                         static_cast<double>(d.bounce), static_cast<double>(d.friction),
                         static_cast<double>(d.density));
        }
    }

    [[noreturn]] static void fail(const World& world, BodyId id, const check::Penetration& p,
                                  int step) {
        finding("settled: after step " + std::to_string(step + 1) + ", " + check::describe(id) +
                " at " + check::describe(world.position(id)) + " half " +
                check::describe(world.halfExtents(id)) + " is " + std::to_string(p.depth) +
                " deep in " + check::describe(p.into) + " at " +
                check::describe(world.position(p.into)) + " half " +
                check::describe(world.halfExtents(p.into)) + "; allowed " +
                std::to_string(p.allowed) + (world.isAwake(id) ? " (awake)" : " (asleep)"));
    }

    void buildFloor(World& world) {
        const float half = 200 * s_, thick = 10 * s_;
        auto wall = [&](float x, float y, float hw, float hh) {
            world.createBody({.type = BodyType::Static, .x = x, .y = y, .hw = hw, .hh = hh});
        };
        switch (in_.byte() % 4) {
        case 0:
            wall(0, above(-thick), half, thick);
            break;
        case 1: {
            // Boxes edge to edge, of different widths: seams.
            float left = -half;
            while (left < half) {
                const float width = s_ * static_cast<float>(8 + in_.byte() % 64);
                wall(left + width / 2, above(-thick), width / 2, thick);
                left += width;
            }
            break;
        }
        case 2: {
            // A tile map: solid rows under the top one, whose tiles are bumps and holes.
            TileMapDef map;
            map.tile = s_ * static_cast<float>(4 + in_.byte() % 29);
            const int columns = static_cast<int>(std::ceil(2 * half / map.tile));
            const int rows = 3;
            const std::uint64_t top = in_.bits() | std::uint64_t{in_.bits()} << 32;
            for (int r = 0; r < rows; ++r) {
                std::string row(static_cast<std::size_t>(columns), '#');
                if (r == 0)
                    for (int c = 0; c < columns; ++c)
                        row[static_cast<std::size_t>(c)] = (top >> (c % 64)) & 1 ? '#' : '.';
                map.rows.push_back(row);
            }
            // Rows read top first in a y-down world, bottom first in a y-up one; the top
            // row (the bumps) rises above y = 0 by one tile.
            if (down_ < 0)
                std::reverse(map.rows.begin(), map.rows.end());
            map.x = -half;
            map.y = down_ > 0 ? -map.tile : -(static_cast<float>(rows) - 1) * map.tile;
            createTileMap(world, map);
            break;
        }
        case 3:
            wall(0, above(-thick), half, thick);
            wall(-half - thick, above(200 * s_), thick, 200 * s_);
            wall(half + thick, above(200 * s_), thick, 200 * s_);
            break;
        }
    }

    BodyDef boxDef() {
        static constexpr std::array<float, 6> densities = {1, 1, 1, 10, 0.1f, 100};
        BodyDef d;
        d.hw = s_ * 0.5f * static_cast<float>(1 + in_.byte() % 24);
        d.hh = s_ * 0.5f * static_cast<float>(1 + in_.byte() % 24);
        d.x = s_ * (static_cast<float>(in_.byte()) - 127.5f) * 1.5f;
        // Above the bumps of a tile floor (at most 32 units high), overlapping one another
        // maybe, never the floor.
        d.y = above(40 * s_ + d.hh + s_ * static_cast<float>(in_.byte()) * 2);
        d.density = densities[in_.byte() % densities.size()];
        const std::uint8_t material = in_.byte();
        d.bounce = static_cast<float>(material % 5) / 4.0f;
        d.friction = static_cast<float>(material / 5 % 5) / 4.0f;
        return d;
    }
};

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    const bool settled = data[0] % 8 == 0;
    // 0xFF: a chaos program with the operations of characters; 0xFE: and ramps (Program).
    const bool characters = data[0] == 0xFF;
    const bool ramps = data[0] == 0xFE;
    // JOSTLE_FUZZ_MODE=chaos or settled confines a campaign to one mode (scripts/fuzz.sh
    // gives each its share of the time: settled runs are slow and rich in coverage, and
    // left to itself libFuzzer spends most of its time on them). Inputs of the other mode
    // are skipped, not reinterpreted, so that a corpus means the same in every mode.
    static const std::string mode =
        std::getenv("JOSTLE_FUZZ_MODE") ? std::getenv("JOSTLE_FUZZ_MODE") : "";
    if ((mode == "chaos" && settled) || (mode == "settled" && !settled))
        return -1; // libFuzzer: do not add this input to the corpus
    Input in(data + 1, size - 1);
    if (settled)
        Settled(in).run();
    else
        Program(in, characters, ramps).run();
    return 0;
}
