// jostle/world.hpp: the world, which owns bodies and steps them.
//
//     jostle::WorldDef def;
//     def.gravity = {0, 800};              // y grows downward, as on screen
//     jostle::World world(def);
//     jostle::BodyId floor = world.createBody({.type = jostle::BodyType::Static,
//                                              .x = 0, .y = 300, .hw = 400, .hh = 10});
//     jostle::BodyId box = world.createBody({.x = 0, .y = 0, .hw = 10, .hh = 10});
//     for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);
//     jostle::Vec2 p = world.position(box);
//
// Misuse (a stale BodyId, NaN, dt <= 0, a setting changed mid-step, ...) throws
// jostle::Error: see error.hpp.
// Same inputs give the same results bit for bit: bodies are processed in creation order.
#pragma once

#include "jostle/body.hpp"
#include "jostle/debug_draw.hpp"
#include "jostle/error.hpp"
#include "jostle/math.hpp"
#include "jostle/tasks.hpp"
#include "jostle/visibility.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace jostle {
JOSTLE_EXPORT_BEGIN

struct TileMapId; // jostle/tilemap.hpp

/// How collisions are resolved (docs/physical-model.md compares the two models).
enum class Solver : std::uint8_t {
    /// The tutorial to the letter: each dynamic body, in creation order, moves and is
    /// pushed out of whatever it overlaps, one pair at a time.
    Classic,
    /// All contacts solved together: stable stacks, mass, momentum, Coulomb friction.
    Physical,
};

/// The names used in scene files: "classic", "physical".
const char* toString(Solver solver);
std::optional<Solver> solverFromString(const std::string& name);

/// Options of the classic model, both from the tutorial's "Physics" section.
struct ClassicOptions {
    /// Off: only the moving body's velocity changes (the tutorial's Response section).
    /// On: the velocity change is an impulse shared by inverse mass, so both bodies of a
    /// dynamic pair change and momentum is conserved; static and kinematic bodies are
    /// infinitely heavy.
    bool mass = false;
    /// On: Coulomb's law; friction takes away at most friction × the normal velocity
    /// change, so a sliding body decelerates at about friction × gravity instead of
    /// losing the fraction `friction` of its speed at every contact.
    bool coulomb = false;
    /// On: continuous collision, as in the physical model; a dynamic body is swept along
    /// its motion and stopped at the first static or kinematic body in its way, so it
    /// cannot pass through thin walls at any speed. Off: the tutorial, tunnelling and all.
    bool ccd = false;
};

/// How the physical model combines the friction of a pair.
enum class FrictionMix : std::uint8_t {
    Min,           ///< the smaller of the two, as the tutorial does (the default)
    GeometricMean, ///< sqrt(a × b), as Box2D does: ice on rubber is slippery, not stuck
};

/// The names used in scene files: "min", "geometricMean".
const char* toString(FrictionMix mix);
std::optional<FrictionMix> frictionMixFromString(const std::string& name);

/// Settings of the physical model (docs/physical-model.md explains each).
/// Tolerances are fractions of body sizes, so they work in pixels and in metres alike.
struct PhysicalOptions {
    /// Sequential-impulse passes over all contacts per step, >= 1. More: stiffer stacks.
    int velocityIterations = 4;
    /// Position-correction passes per step, >= 0.
    int positionIterations = 3;
    /// Penetration left alone so that resting contacts stay in touch and do not jitter,
    /// as a fraction of the smaller half extent of the pair along the normal; in [0, 0.5].
    float slop = 0.01f;
    /// Fraction of the remaining penetration (beyond the slop) removed per position pass,
    /// in (0, 1]. Corrections move bodies, never their velocities: no energy is added.
    float correction = 0.2f;
    /// A contact approaching slower than this does not bounce (so that resting bodies do
    /// not buzz), >= 0. 0 means automatic: twice what gravity adds in one step, 2 |g| dt.
    float restitutionThreshold = 0.0f;
    FrictionMix frictionMix = FrictionMix::Min;
    /// The most bodies a dynamic body may be in contact with in one step, in [1, 65536]:
    /// so many moving ones and as many at rest (static or asleep). It bounds a step's
    /// memory, at every worker count, whatever the scene holds: a pile of bodies dropped
    /// at one spot costs at most bodies × 2 × this many contacts, and the stages after the
    /// pair search work on those alone (the search still meets every overlapping pair once:
    /// 10,000 bodies at one spot take about half a second a step). Pairs beyond it, in the
    /// broadphase's fixed order, are left out of that step (they pass into each other);
    /// World::pairsLeftOut() counts them. No sensible scene comes near the default.
    int maxContactsPerBody = 64;
};

/// Everything that describes a world. The names are those of scene files.
struct WorldDef {
    /// Acceleration of every dynamic body, scaled by its gravityScale.
    Vec2 gravity{0.0f, 0.0f};
    /// The largest speed (length of the velocity vector) of a dynamic body, > 0.
    /// Infinity (the default) means no clamp.
    float maxVelocity = std::numeric_limits<float>::infinity();
    Solver solver = Solver::Physical;
    ClassicOptions classic{};
    PhysicalOptions physical{};
    /// Bodies at rest for a while, and every body they touch, fall asleep together and
    /// cost next to nothing (they are left out of the solver and the pair search) until
    /// something wakes them (physical model only; docs/sleeping.md).
    bool sleeping = true;
    /// Threads to step on (jostle/tasks.hpp): by default the calling thread alone. The
    /// results are the same, bit for bit, with any number.
    TaskSystem tasks{};
};

/// The first problem with `def`, or nothing if it is acceptable.
std::optional<FieldError> checkWorldDef(const WorldDef& def);

/// A pair about to collide, as the solver sees it before it responds. The pre-solve
/// callback may change bounce and friction, for this pair and this step only.
struct Collision {
    BodyId a; ///< classic: the dynamic body that moved; physical: the one created first
    BodyId b; ///< the other body
    /// Unit, pointing from b towards a: along x or y between two sharp boxes; for a pair
    /// with a rounded body, ramp or segment, the normal where they touch (as ContactEvent's).
    Vec2 normal;
    /// How deep they overlap along the normal. Negative for a pair still apart that will
    /// meet within the step (the physical model's speculative contacts: -depth is the
    /// gap); 0 where the classic ccd option's sweep stopped a body against another.
    float depth;
    float bounce; ///< max of the pair's bounce
    /// The pair's friction as the world mixes it (min, or geometric mean), in [0, 1]. A
    /// value set here is clamped to [0, 1]; unless lowered, a character keeps its firm
    /// footing on a slope it stands on (it walks there as on level ground).
    float friction;
};

/// Two bodies that started or stopped touching.
struct ContactEvent {
    BodyId a; ///< the body created first
    BodyId b;
    /// Unit, pointing from b towards a: along x or y between two sharp boxes. For a pair
    /// with a rounded body, ramp or segment (docs/slopes-and-shapes.md), the normal of the
    /// surfaces where they touch: a slope's, or any direction round a curve or a corner.
    Vec2 normal;
    /// Begin: how fast they closed along the normal when they met (>= 0). End: 0.
    float approachSpeed;
    /// Begin: where they touch, halfway between the two surfaces along the normal. Where a
    /// face meets a face (two boxes, a box against a ramp's leg, a capsule's side against a
    /// wall), the middle of the stretch they share; where a corner or a curve touches, that
    /// point: a box's corner on a slope, a circle's centre less its radius times the
    /// normal, the corner a circle rolls round. End: {0, 0}.
    Vec2 point;
};

/// A contact of one body with another, as World::contacts lists it.
struct ContactInfo {
    BodyId other;
    Vec2 normal;   ///< unit, pointing from `other` towards the body (as ContactEvent's)
    Vec2 point;    ///< where they touch now, as in a ContactEvent's begin
    float impulse; ///< the normal impulse between them in the last step (mass × speed)
};

/// What a body stands on (World::ground).
struct Ground {
    BodyId body; ///< the body under it
    Vec2 normal; ///< the push of the ground: against gravity
    /// The ground's velocity now: what a rider moves with (a conveyor's surface velocity
    /// along its surface included).
    Vec2 velocity;
};

/// A body that started or stopped overlapping a sensor.
struct SensorEvent {
    BodyId sensor;
    BodyId visitor;
};

/// A body squeezed between a kinematic body moving into it and something on the other
/// side that would not give way (a static or kinematic body, or a pile resting on one).
struct CrushEvent {
    BodyId body;
    BodyId by;      ///< the kinematic body pushing
    BodyId against; ///< what is on the other side
};

/// What a body touched during the last step, relative to gravity: the floor is below,
/// the direction gravity pulls (with no gravity: y grows downward, as on screen).
struct Touching {
    /// Pushed up by a surface within the body's floorAngle of level (BodyDef::floorAngle).
    bool floor = false;
    /// Pushed down by a surface within 60 degrees of level.
    bool ceiling = false;
    /// Anything else pushes it sideways: a wall, or a slope too steep to be its floor.
    bool wallLeft = false;  ///< on the body's left, looking along gravity's "down"
    bool wallRight = false; ///< on the body's right
};

/// Where the last step's time went, in milliseconds of wall-clock time: for finding what
/// a scene costs, never part of the results. The physical model fills every stage; the
/// classic model fills `step` only.
struct StepProfile {
    float step = 0.0f; ///< the whole of step(), the stages below and the rest
    // The physical model's stages, in the order a step runs them (docs/architecture.md).
    float riders = 0.0f;     ///< carrying what stands on moving platforms
    float velocities = 0.0f; ///< forces, gravity, damping, the clamp, characters' walks
    float pairs = 0.0f;      ///< the broadphase: its grids, and the pairs that may touch
    float corners = 0.0f;    ///< slipping round corners and up steps
    float contacts = 0.0f;   ///< contacts made of the pairs, warm-started from the last step
    float support = 0.0f;    ///< ordering contacts from the ground up
    float impacts = 0.0f;    ///< collisions and bounces
    float layers = 0.0f;     ///< cutting the contacts into layers, for threads
    float solve = 0.0f;      ///< the solver's velocity passes
    float shock = 0.0f;      ///< shock propagation
    float bounces = 0.0f;    ///< settling bounces the contacts did not let happen
    float sweeps = 0.0f;     ///< continuous collision
    float positions = 0.0f;  ///< moving the bodies by their velocities
    float correction = 0.0f; ///< position correction
    float snap = 0.0f;       ///< snapping to the ground
    float store = 0.0f;      ///< what the next step remembers of this one (contacts, platforms)
    float events = 0.0f;     ///< contact, sensor and crush events
    float sleep = 0.0f;      ///< islands falling asleep
};

/// StepProfile's fields by name, in its order: what the C API, the Lua module and the
/// benchmark read it by.
struct StepProfileField {
    const char* name;
    float StepProfile::*ms;
};
inline constexpr StepProfileField kStepProfileFields[] = {
    {"step", &StepProfile::step},
    {"riders", &StepProfile::riders},
    {"velocities", &StepProfile::velocities},
    {"pairs", &StepProfile::pairs},
    {"corners", &StepProfile::corners},
    {"contacts", &StepProfile::contacts},
    {"support", &StepProfile::support},
    {"impacts", &StepProfile::impacts},
    {"layers", &StepProfile::layers},
    {"solve", &StepProfile::solve},
    {"shock", &StepProfile::shock},
    {"bounces", &StepProfile::bounces},
    {"sweeps", &StepProfile::sweeps},
    {"positions", &StepProfile::positions},
    {"correction", &StepProfile::correction},
    {"snap", &StepProfile::snap},
    {"store", &StepProfile::store},
    {"events", &StepProfile::events},
    {"sleep", &StepProfile::sleep},
};

/// Called for every pair the solver is about to respond to (overlapping, touching, or
/// in the physical model about to touch within the step) before it responds. Return
/// false to let the pair pass through each other this time (a one-way platform, a ghost,
/// a team mate).
using PreSolveFn = std::function<bool(Collision&)>;

class World {
public:
    /// Throws jostle::Error if checkWorldDef(def) finds a problem, or if this process has
    /// already made UINT32_MAX (4,294,967,295) worlds: each world takes a serial number
    /// of its own, never given again, which its handles carry (BodyId::world).
    explicit World(const WorldDef& def = {});
    ~World();
    World(World&&) noexcept;
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // --- Bodies ------------------------------------------------------------------------

    /// Adds a body. Throws jostle::Error if checkBodyDef(def) finds a problem.
    /// Called from a callback during step(), the body exists at once but takes part
    /// in the simulation from the next step on.
    BodyId createBody(const BodyDef& def);

    /// Removes a body; its handle and every copy of it become stale at once.
    /// Safe from a callback during step(): the body is left out of the rest of the step
    /// and its storage is reclaimed when the step ends. Costs the same whatever the
    /// number of bodies (amortised: see bodies()).
    void destroyBody(BodyId id);

    /// True if `id` names a body of this world that has not been destroyed.
    bool isValid(BodyId id) const;
    /// True if `id` names a tile map of this world (jostle/tilemap.hpp) that has not been
    /// destroyed.
    bool isValid(TileMapId id) const;

    /// This world's handle of the body `id` names in another world: the body of the same
    /// slot and generation here, or the null handle if there is none alive. For handles
    /// kept across a snapshot restored into another world (a saved game loaded by a new
    /// run, a peer's state; docs/snapshots.md): a body keeps its slot and generation. The
    /// world `id` came from does not matter (a BodyId{index, generation} saved as numbers
    /// is adopted too).
    BodyId adopt(BodyId id) const;
    /// The same for a tile map.
    TileMapId adopt(TileMapId id) const;

    /// The live bodies, in creation order. Invalidated by createBody and destroyBody.
    /// destroyBody leaves a gap in the list, which the next call of this function (or
    /// of step(), or a query) closes, in time proportional to the number of bodies; so
    /// does destroyBody itself once gaps are half the list.
    std::span<const BodyId> bodies() const;
    /// How many bodies are alive: bodies().size(), without closing gaps.
    std::size_t bodyCount() const;

    /// Copies the positions of the bodies, in the order of bodies(), into `out`: as many
    /// as fit (all of them if out.size() >= bodyCount()). Returns how many. One call
    /// for a whole world: for drawing, and for bindings where a call per body costs.
    std::size_t readPositions(std::span<Vec2> out) const;
    /// The same for their velocities.
    std::size_t readVelocities(std::span<Vec2> out) const;
    /// The same for their half extents (halfExtents): with the positions, every box to draw.
    std::size_t readHalfExtents(std::span<Vec2> out) const;

    /// Draws the world as the engine sees it through the game's renderer: every body in
    /// its shape and colour, and what `options` asks for (jostle/debug_draw.hpp).
    void debugDraw(DebugDraw& draw, const DebugDrawOptions& options = {}) const;

    /// The body as a definition: its current position, velocity and settings.
    BodyDef bodyDef(BodyId id) const;

    BodyType type(BodyId id) const;
    /// Throws jostle::Error to make a ramp or segment dynamic: they are static or
    /// kinematic. A body's shape (BodyDef::radius, slope, segment) is fixed at creation;
    /// bodyDef gives it back.
    void setType(BodyId id, BodyType type);

    Vec2 position(BodyId id) const;
    /// Moves the body there at once (a teleport: nothing is swept on the way).
    void setPosition(BodyId id, Vec2 centre);

    Vec2 velocity(BodyId id) const;
    void setVelocity(BodyId id, Vec2 velocity);

    /// Half width and half height; never below the body's radius (else jostle::Error).
    Vec2 halfExtents(BodyId id) const;
    void setHalfExtents(BodyId id, Vec2 halfExtents);

    float bounce(BodyId id) const;
    void setBounce(BodyId id, float bounce);
    float friction(BodyId id) const;
    void setFriction(BodyId id, float friction);

    /// The mass the solver uses: the explicit mass, or density × area; infinity for
    /// static and kinematic bodies.
    float mass(BodyId id) const;
    /// Sets an explicit mass, > 0.
    void setMass(BodyId id, float mass);
    /// Drops any explicit mass: the mass becomes density × area from now on.
    void setDensity(BodyId id, float density);

    float gravityScale(BodyId id) const;
    void setGravityScale(BodyId id, float scale);
    float damping(BodyId id) const;
    void setDamping(BodyId id, float damping);
    bool isBullet(BodyId id) const;
    void setBullet(BodyId id, bool bullet);
    /// False while the body sleeps (see WorldDef::sleeping). Sleeping bodies wake when an
    /// awake body touches them; when a setter of their physics (type, position,
    /// velocity, size, bounce, friction, mass, density, gravity scale, damping) changes
    /// them or a body they rest on; when such a body is destroyed; and when the world's
    /// gravity, model or sleeping setting changes. setBullet and setUserData wake nothing.
    /// A sleeping body keeps the separation() of its last awake step.
    bool isAwake(BodyId id) const;
    /// Wakes the body and everything it rests on or carries; it can fall asleep again
    /// only after being at rest for the time sleep needs.
    void wake(BodyId id);
    void* userData(BodyId id) const;
    void setUserData(BodyId id, void* data);

    /// See BodyDef::surfaceVelocity (finite; {0, 0} for a dynamic body, else
    /// jostle::Error). Wakes what rests on the body.
    Vec2 surfaceVelocity(BodyId id) const;
    void setSurfaceVelocity(BodyId id, Vec2 velocity);
    /// See BodyDef::oneWay. Throws jostle::Error for a normal that is not {0, 0} or a
    /// unit vector along x or y, and for a rounded body, ramp or segment.
    Vec2 oneWay(BodyId id) const;
    void setOneWay(BodyId id, Vec2 normal);
    /// Lets the body fall through every one-way platform for the next `seconds` (>= 0):
    /// "down + jump" in a platformer. 0 ends it. Only a dynamic body drops through: for a
    /// static or kinematic body it throws jostle::Error, as for seconds < 0.
    void dropThrough(BodyId id, float seconds);

    /// See BodyDef::category and BodyDef::mask.
    std::uint32_t category(BodyId id) const;
    void setCategory(BodyId id, std::uint32_t bits);
    std::uint32_t mask(BodyId id) const;
    void setMask(BodyId id, std::uint32_t bits);
    /// See BodyDef::sensor.
    bool isSensor(BodyId id) const;
    void setSensor(BodyId id, bool sensor);

    // --- Characters (docs/characters.md) ----------------------------------------------

    /// See BodyDef::character.
    bool isCharacter(BodyId id) const;
    void setCharacter(BodyId id, bool character);
    /// See BodyDef::wallFriction: in [0, 1].
    float wallFriction(BodyId id) const;
    void setWallFriction(BodyId id, float friction);
    /// See BodyDef::floorAngle: degrees in [0, 90). Counts from the next step's contacts.
    float floorAngle(BodyId id) const;
    void setFloorAngle(BodyId id, float degrees);
    /// See BodyDef::snapDown: >= 0, 0 is off.
    float snapDown(BodyId id) const;
    void setSnapDown(BodyId id, float distance);
    /// See BodyDef::cornerCorrection and stepUp: >= 0, else jostle::Error.
    float cornerCorrection(BodyId id) const;
    void setCornerCorrection(BodyId id, float distance);
    float stepUp(BodyId id) const;
    void setStepUp(BodyId id, float height);
    /// The speed a character walks at (finite): along what it stands on and relative to
    /// it, so that it keeps pace with a lift; positive to the right of gravity's "down"
    /// (+x in a y-down world); in the air, relative to the world. It holds until changed:
    /// set it from the input every frame (0 stands still). Each step it walks at this
    /// speed across gravity unless something stops it (a wall; crates heavier than its
    /// feet's grip can push: docs/characters.md); along gravity the velocity is the
    /// physics' (set it to jump). Throws
    /// jostle::Error for a body that is not a character (a dynamic body with
    /// BodyDef::character): forgetting the flag would otherwise walk nothing, silently.
    float walkSpeed(BodyId id) const;
    void setWalkSpeed(BodyId id, float speed);
    /// What the body stood on at the end of the last step: of the bodies that pushed it
    /// against gravity (floors, in touching()'s sense), the one that pushed hardest.
    /// Nothing in the air, nor if that body has been destroyed since. A sleeping body
    /// keeps the ground it fell asleep on.
    std::optional<Ground> ground(BodyId id) const;

    // --- Forces ------------------------------------------------------------------------

    /// Adds a force (mass × units / s²) at the body's centre for the next step: its
    /// velocity changes by force / mass × dt then. Forces add up until that step, which
    /// clears them: apply a lasting force before every step. Wakes the body. Static and
    /// kinematic bodies are infinitely heavy: nothing happens to them.
    void applyForce(BodyId id, Vec2 force);
    /// Changes the body's velocity by impulse / mass (mass × units / s) at once: a kick,
    /// a blast, a jump of a given strength. Wakes the body. Nothing happens to static and
    /// kinematic bodies.
    void applyImpulse(BodyId id, Vec2 impulse);

    // --- Contacts now --------------------------------------------------------------------

    /// The bodies this one touched at the end of the last step (sensors excluded, and
    /// bodies destroyed since), in the order of the bodies they pair with, created first
    /// first. `out` is cleared first.
    void contacts(BodyId id, std::vector<ContactInfo>& out) const;
    std::vector<ContactInfo> contacts(BodyId id) const;
    /// True if the two touched at the end of the last step.
    bool isTouching(BodyId a, BodyId b) const;

    /// The sum of the separation vectors that pushed this body out of others during the
    /// last step. Pushed up by a floor in a y-down world means separation().y < 0: that
    /// is how a game tells that its character is standing on something.
    Vec2 separation(BodyId id) const;

    // --- What the last step did (docs/events.md) --------------------------------------
    //
    // Each is an array filled by step() and kept until the next step(): read them after
    // stepping. Pairs appear in a fixed order, the same run after run.

    /// Pairs that started touching in the last step (sensors excluded).
    std::span<const ContactEvent> contactBegins() const;
    /// Pairs that stopped touching in the last step, or whose body was destroyed.
    std::span<const ContactEvent> contactEnds() const;
    /// A body started or stopped overlapping a sensor in the last step.
    std::span<const SensorEvent> sensorBegins() const;
    std::span<const SensorEvent> sensorEnds() const;
    /// Crushes that began in the last step: a body squeezed between a moving kinematic
    /// body and something that would not give way (physical model). Each squeeze begins
    /// once. From then on the body and the kinematic body pass through each other (no
    /// contact, no push) and the body stays where what holds it keeps it, until the two no
    /// longer overlap: that ends the crush. The game decides (kill, or rescue).
    std::span<const CrushEvent> crushBegins() const;
    /// Crushes that ended in the last step: the two bodies no longer overlap, or one of
    /// them was destroyed.
    std::span<const CrushEvent> crushEnds() const;
    /// Pairs of bodies the last step left out because a dynamic body had more than
    /// PhysicalOptions::maxContactsPerBody of them (physical model): 0 in a sane scene.
    std::uint64_t pairsLeftOut() const;
    /// What the body touched in the last step, relative to gravity (physical model).
    Touching touching(BodyId id) const;
    /// Where the last step's time went, stage by stage (all 0 before the first step).
    const StepProfile& profile() const;

    // --- The world ---------------------------------------------------------------------

    /// Advances the world by dt seconds (dt > 0 and finite, else jostle::Error).
    ///
    /// From inside a callback of this world (the pre-solve), bodies may be read, created,
    /// destroyed and changed, tiles set, and queries asked. Calling step() or any of the
    /// world's setters below (gravity to pre-solve) throws jostle::Error: the step reads
    /// them throughout. Destroying or move-assigning the World itself from its callback
    /// stops the program with a message (a destructor cannot throw). In the physical
    /// model the solver takes a body's mass when the step first meets it (in its first
    /// pair): a mass or type a callback changes for a body met already counts from the
    /// next step. What the callback throws comes out of step() once the step is whole: the
    /// step goes on as if the callback had answered true from then on (it is not asked
    /// again in that step, and what it changed of the Collision it threw from is not kept).
    void step(float dt);

    Vec2 gravity() const;
    void setGravity(Vec2 gravity);
    float maxVelocity() const;
    /// > 0; infinity for no clamp.
    void setMaxVelocity(float maxVelocity);
    Solver solver() const;
    /// Throws jostle::Error for the classic model while the world has bodies that are not
    /// sharp boxes, or a tile map has ramp tiles (even one whose ramp bodies the game
    /// destroyed): the tutorial's model has boxes only, and createBody refuses the others
    /// there.
    void setSolver(Solver solver);
    bool sleeping() const;
    /// Turning sleeping off wakes every body.
    void setSleeping(bool enabled);
    /// How many threads step the world (WorldDef::tasks.workers), fixed at its creation.
    int workers() const;
    ClassicOptions classicOptions() const;
    void setClassicOptions(ClassicOptions options);
    PhysicalOptions physicalOptions() const;
    /// Throws jostle::Error if an option is out of its range.
    void setPhysicalOptions(PhysicalOptions options);

    /// Installs the pre-solve callback (an empty function removes it).
    void setPreSolve(PreSolveFn callback);

    // --- Snapshots: saving and restoring the whole world (docs/snapshots.md) -----------
    //
    // A snapshot holds everything that decides the world's future: every body with its
    // settings and run-time state, the contact cache, the last step's touching pairs,
    // crushes and sleeping islands, the tile maps, the settings and the handles' slots.
    // Its bytes are the same on every machine and build (little-endian, versioned,
    // checksummed): a world restored from it, anywhere, at any worker count, steps on bit
    // for bit as the one it was taken from. What is not in it: userData, the pre-solve
    // callback and the workers (the restoring world's own), and the last step's events
    // (empty after a restore). All four throw jostle::Error from a callback during step()
    // or move().

    /// The length in bytes of a snapshot of the world as it is now.
    std::size_t snapshotSize() const;
    /// Writes a snapshot of the world into `out` and returns its length; allocates
    /// nothing. Throws jostle::Error if `out` is shorter than snapshotSize().
    std::size_t snapshot(std::span<std::byte> out) const;
    /// A snapshot of the world, in a vector of its own.
    std::vector<std::byte> snapshot() const;
    /// Makes the world what it was when `snapshot` was taken, of this world or another.
    /// Handles held then are valid again (a body destroyed since is back under its old
    /// handle); bodies and tile maps created since are gone, their handles stale. A body
    /// keeps its userData if its slot still holds it or held it last. Throws jostle::Error,
    /// leaving the world exactly as it was, for bytes that are not a whole snapshot of
    /// this format (truncated, corrupted, of another format version, or not a snapshot).
    void restore(std::span<const std::byte> snapshot);
    /// A 64-bit hash of exactly what a snapshot holds (its checksum, XXH64), computed
    /// without writing one: equal on two peers whose worlds are the same, bit for bit.
    std::uint64_t stateHash() const;

private:
    friend struct WorldAccess; // the internals' way in (src/world_access.hpp)
    std::unique_ptr<struct WorldState> state_;
};

JOSTLE_EXPORT_END
} // namespace jostle
