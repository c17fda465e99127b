// Snapshots (docs/snapshots.md): a world restored from one steps on bit for bit as the world
// it was taken from, in place (rollback) or in another world, at another worker count;
// handles are kept as they were; bad bytes are refused by name and change nothing.
#include "busy_worlds.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "physical/contact_cache.hpp"
#include "snapshot/access.hpp"
#include "snapshot/xxhash64.hpp"
#include "world_access.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace jostle;
using namespace jostle::testing;
using Bytes = std::vector<std::byte>;

constexpr float kDt = 1.0f / 60.0f;

std::uint64_t checksumOf(const Bytes& snapshot) {
    std::uint64_t v = 0;
    for (int i = 7; i >= 0; --i)
        v = v << 8 | std::to_integer<std::uint64_t>(snapshot[24 + static_cast<std::size_t>(i)]);
    return v;
}

/// `ids` as handles of `world` (the same slots and generations, another world's serial).
std::vector<BodyId> handlesIn(const World& world, std::vector<BodyId> ids) {
    const std::uint32_t serial = world.bodies().empty() ? 0 : world.bodies()[0].world;
    for (BodyId& id : ids)
        id.world = serial;
    return ids;
}

// --- The hash ---------------------------------------------------------------------------

TEST(Snapshots, TheChecksumIsXxh64AsPublished) {
    // XXH64 with seed 0 of "", "a", "abc" and the pangram, from xxHash's published values.
    auto of = [](const std::string& s) {
        return snapshot::xxHash64(reinterpret_cast<const std::uint8_t*>(s.data()), s.size());
    };
    EXPECT_EQ(of(""), 0xEF46DB3751D8E999ull);
    EXPECT_EQ(of("a"), 0xD24EC4F1A98C6E5Bull);
    EXPECT_EQ(of("abc"), 0x44BC2CF5AD770999ull);
    EXPECT_EQ(of("The quick brown fox jumps over the lazy dog"), 0x0B242D361FDA71BCull);
    // Fed a byte at a time, the same.
    snapshot::XxHash64 pieces;
    for (char c : std::string("The quick brown fox jumps over the lazy dog"))
        pieces.update(reinterpret_cast<const std::uint8_t*>(&c), 1);
    EXPECT_EQ(pieces.digest(), 0x0B242D361FDA71BCull);
}

// --- Round trips and rollback -------------------------------------------------------------

TEST(Snapshots, ARestoredWorldSnapshotsToTheSameBytesAndHash) {
    BusyWorld busy(Solver::Physical);
    for (int step = 0; step < 400; ++step)
        busy.step();
    const Bytes saved = busy.world.snapshot();
    EXPECT_EQ(saved.size(), busy.world.snapshotSize());
    EXPECT_EQ(busy.world.stateHash(), checksumOf(saved));

    World other;
    other.restore(saved);
    EXPECT_EQ(other.snapshot(), saved);
    EXPECT_EQ(other.stateHash(), busy.world.stateHash());
    EXPECT_EQ(other.bodyCount(), busy.world.bodyCount());
}

/// The last step's touching pairs of `world`, as the events compare them.
std::vector<TouchRecord> touchingOf(const World& world) {
    return WorldAccess::state(world).events.touchingBefore();
}

bool sameRecords(const std::vector<TouchRecord>& x, const std::vector<TouchRecord>& y) {
    return x.size() == y.size() &&
           std::memcmp(x.data(), y.data(), x.size() * sizeof(TouchRecord)) == 0;
}

/// Restored from `world`'s snapshot, a world holds its touching pairs to the bit, in order.
void expectTouchingComesBack(const World& world) {
    World restored;
    restored.restore(world.snapshot());
    EXPECT_TRUE(sameRecords(touchingOf(restored), touchingOf(world)));
}

TEST(Snapshots, TheTouchingPairsComeBackToTheBitInTheirOrder) {
    // The events compare the next step's pairs with these: each kind of list comes back as
    // it was (a format that writes a pair with its contact cache entry must keep this).
    for (Solver solver : {Solver::Physical, Solver::Classic}) { // the classic: no cache
        BusyWorld busy(solver);
        for (int step = 0; step < 250; ++step)
            busy.step();
        ASSERT_GT(touchingOf(busy.world).size(), 50u);
        expectTouchingComesBack(busy.world);
    }
    // A floor under 40 boxes: a run of the cache longer than 16, lying by the other slot,
    // and the floor is created last, so that each pair's first body is the box.
    World row(WorldDef{.gravity = {0, 600}});
    for (int i = 0; i < 40; ++i)
        row.createBody({.x = 10.0f * float(i), .y = -5.0f, .hw = 5, .hh = 5});
    const BodyId floor = row.createBody({.type = BodyType::Static, .y = 10, .hw = 500, .hh = 10});
    for (int step = 0; step < 20; ++step)
        row.step(kDt);
    EXPECT_EQ(row.contacts(floor).size(), 40u);
    expectTouchingComesBack(row);
    // Columns asleep among awake ones: the sleepers' pairs are carried over, with no cache
    // entry, between the others'.
    World columns(WorldDef{.gravity = {0, 600}});
    columns.createBody({.type = BodyType::Static, .y = 10, .hw = 500, .hh = 10});
    std::vector<BodyId> bottoms;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 6; ++c) {
            const BodyId id = columns.createBody(
                {.x = 30.0f * float(c), .y = -5.0f - 10.0f * float(r), .hw = 5, .hh = 5});
            if (r == 0)
                bottoms.push_back(id);
        }
    for (int step = 0; step < 300; ++step)
        columns.step(kDt);
    for (int step = 0; step < 5; ++step) {
        for (std::size_t c = 1; c < bottoms.size(); c += 2)
            columns.wake(bottoms[c]);
        columns.step(kDt);
    }
    ASSERT_FALSE(columns.isAwake(bottoms[0]));
    ASSERT_TRUE(columns.isAwake(bottoms[1]));
    EXPECT_EQ(touchingOf(columns).size(), 24u);
    expectTouchingComesBack(columns);
}

/// Steps `scene` `steps` steps, snapshots it, steps `steps` more; then restores the
/// snapshot and the script's state and steps again: the world's states and the hashes
/// of what it reported agree step for step.
template <class Scene> void expectRollbackRepeats(Scene& scene, int before, int after) {
    for (int step = 0; step < before; ++step)
        scene.step();
    const Bytes saved = scene.world.snapshot();
    const auto script = scene.script();
    const Hash hash = scene.hash;
    std::vector<std::uint64_t> states;
    for (int step = 0; step < after; ++step) {
        scene.step();
        states.push_back(scene.world.stateHash());
    }
    const std::uint64_t reported = scene.hash.value();

    scene.world.restore(saved);
    scene.setScript(script);
    scene.hash = hash;
    for (int step = 0; step < after; ++step) {
        scene.step();
        ASSERT_EQ(scene.world.stateHash(), states[static_cast<std::size_t>(step)])
            << "step " << step << " after the restore";
    }
    EXPECT_EQ(scene.hash.value(), reported);
}

TEST(Snapshots, RolledBackThePhysicalBusyWorldRepeatsItself) {
    BusyWorld busy(Solver::Physical);
    expectRollbackRepeats(busy, 300, 300);
}

TEST(Snapshots, RolledBackTheClassicBusyWorldRepeatsItself) {
    BusyWorld busy(Solver::Classic);
    expectRollbackRepeats(busy, 300, 300);
}

TEST(Snapshots, RolledBackTheSlopesWorldRepeatsItself) {
    SlopesWorld slopes;
    expectRollbackRepeats(slopes, 300, 300);
}

/// The sync test of `jostle synctest`, over a scripted scene: after every step t >= k, roll
/// back to the state after step t - k (the world, the script, the hash of what it
/// reported) and step the k steps again: the state hash is the one of the first time.
template <class Scene> void expectSyncTest(Scene& scene, int steps, int k) {
    struct Saved {
        Bytes bytes;
        typename Scene::Script script;
        Hash hash;
    };
    std::vector<Saved> saved{{scene.world.snapshot(), scene.script(), scene.hash}};
    std::vector<std::uint64_t> states{scene.world.stateHash()};
    for (int t = 1; t <= steps; ++t) {
        scene.step();
        saved.push_back({scene.world.snapshot(), scene.script(), scene.hash});
        states.push_back(scene.world.stateHash());
        if (t < k)
            continue;
        const Saved& back = saved[static_cast<std::size_t>(t - k)];
        scene.world.restore(back.bytes);
        scene.setScript(back.script);
        scene.hash = back.hash;
        for (int again = t - k + 1; again <= t; ++again)
            scene.step();
        ASSERT_EQ(scene.world.stateHash(), states[static_cast<std::size_t>(t)])
            << "step " << t << ", rolled back " << k;
        ASSERT_EQ(scene.hash.value(), saved[static_cast<std::size_t>(t)].hash.value())
            << "what step " << t << " reported, rolled back " << k;
    }
}

// Steps of the sync tests: fewer under a sanitizer, which looks for faults, not for other
// numbers (JOSTLE_TESTS_FEWER_SAMPLES).
#if JOSTLE_TESTS_FEWER_SAMPLES
constexpr int kSyncSteps = 120;
#else
constexpr int kSyncSteps = 300;
#endif

TEST(Snapshots, TheBusyWorldsPassTheSyncTestRolledBack1And2And8Steps) {
    for (int k : {1, 2, 8}) {
        BusyWorld physical(Solver::Physical);
        expectSyncTest(physical, kSyncSteps, k);
        BusyWorld classic(Solver::Classic);
        expectSyncTest(classic, kSyncSteps, k);
        SlopesWorld slopes;
        expectSyncTest(slopes, kSyncSteps, k);
    }
}

/// What the busy worlds do not: a kinematic block coming down again and again onto boxes on
/// the floor (crushes begun, under way and ended), a character walking to and fro and
/// dropping through a one-way platform now and then, impulses, and a pile falling asleep.
class CrushAndDropWorld {
public:
    CrushAndDropWorld() : world(WorldDef{.gravity = {0.0f, 600.0f}}) {
        world.createBody({.type = BodyType::Static, .y = 10, .hw = 300, .hh = 10});
        world.createBody(
            {.type = BodyType::Static, .x = 150, .y = -60, .hw = 60, .hh = 4, .oneWay = {0, -1}});
        block_ = world.createBody(
            {.type = BodyType::Kinematic, .x = -100, .y = -120, .hw = 30, .hh = 10, .vy = 90});
        for (int i = 0; i < 3; ++i)
            world.createBody({.x = -110.0f + 10.0f * float(i), .y = -5, .hw = 5, .hh = 5});
        for (int i = 0; i < 6; ++i)
            world.createBody({.x = 250.0f, .y = -5.0f - 10.0f * float(i), .hw = 5, .hh = 5});
        hero_ = world.createBody({.x = 150, .y = -90, .hw = 6, .hh = 9, .character = true});
    }

    void step() {
        const int step = script_.steps++;
        if (step % 150 == 75) // down through the floor and back up
            turnRound(world, block_);
        if (step % 100 == 0)
            world.setWalkSpeed(hero_, step % 200 == 0 ? 80.0f : -80.0f);
        if (step % 120 == 30 && world.ground(hero_))
            world.applyImpulse(hero_, {0, -world.mass(hero_) * 400.0f});
        if (step % 90 == 60)
            world.dropThrough(hero_, 0.3f);
        world.step(kDt);
        hashStep(world, hash);
        crushes += world.crushBegins().size();
        dropping += WorldAccess::state(world).slots[hero_.index].dropThroughTime > 0.0f ? 1 : 0;
    }

    struct Script {
        int steps = 0;
    };
    Script script() const { return script_; }
    void setScript(const Script& script) { script_ = script; }

    World world;
    Hash hash;
    std::size_t crushes = 0;  ///< begun, over the run
    std::size_t dropping = 0; ///< steps the character spent dropping through

private:
    Script script_;
    BodyId block_, hero_;
};

TEST(Snapshots, CrushesDropsAndSleepPassTheSyncTestRolledBack1And2And8Steps) {
    for (int k : {1, 2, 8}) {
        CrushAndDropWorld scene;
        expectSyncTest(scene, 400, k);
        // The run had what it is here for (counted the first time through each step and
        // again in each re-simulation: more than once, but never zero).
        EXPECT_GT(scene.crushes, 0u);
        EXPECT_GT(scene.dropping, 0u);
        std::size_t asleep = 0;
        for (BodyId id : scene.world.bodies())
            asleep += scene.world.isAwake(id) ? 0 : 1;
        EXPECT_GE(asleep, 6u) << "the pile at x = 250 sleeps";
    }
}

TEST(Snapshots, ASnapshotAtOneWorkerContinuesTheSameAtFourInAnotherWorld) {
    BusyWorld one(Solver::Physical);
    BusyWorld four(Solver::Physical, {.workers = 4});
    WorldAccess::state(four.world).tasks->setBlockSizeForTesting(7);
    for (int step = 0; step < 200; ++step)
        one.step();
    four.world.restore(one.world.snapshot());
    auto script = one.script();
    script.rain = handlesIn(four.world, script.rain);
    four.setScript(script);
    four.hash = one.hash;
    for (int step = 0; step < 300; ++step) {
        one.step();
        four.step();
        ASSERT_EQ(one.world.stateHash(), four.world.stateHash()) << "step " << step;
    }
    EXPECT_EQ(one.hash.value(), four.hash.value());
}

// --- Handles ---------------------------------------------------------------------------------

TEST(Snapshots, HandlesHeldAtTheSnapshotAreValidAgainAndLaterOnesStale) {
    World world(WorldDef{.gravity = {0, 10}});
    int tag = 7;
    const BodyId kept = world.createBody({.x = 0, .hw = 1, .hh = 1, .userData = &tag});
    const BodyId destroyedLater = world.createBody({.x = 5, .hw = 1, .hh = 1});
    const Bytes saved = world.snapshot();

    world.destroyBody(destroyedLater);
    const BodyId createdLater = world.createBody({.x = 9, .hw = 1, .hh = 1});
    world.step(kDt);
    world.restore(saved);

    EXPECT_TRUE(world.isValid(kept));
    EXPECT_TRUE(world.isValid(destroyedLater));
    EXPECT_FALSE(world.isValid(createdLater));
    EXPECT_EQ(world.bodyCount(), 2u);
    EXPECT_EQ(world.userData(kept), &tag); // the process's, kept by the slot that holds it
    EXPECT_EQ(world.position(destroyedLater), (Vec2{5, 0}));
    EXPECT_THROW(world.position(createdLater), Error);

    // Done again, what was done since gives the same handles: rollback keeps them.
    world.destroyBody(destroyedLater);
    EXPECT_EQ(world.createBody({.x = 9, .hw = 1, .hh = 1}), createdLater);
}

TEST(Snapshots, TileMapsComeBackWithTheirTiles) {
    World world(WorldDef{.gravity = {0, 10}});
    const TileMapId map = createTileMap(world, {.tile = 1, .rows = {"#..#", "####"}});
    const Bytes saved = world.snapshot();
    setTile(world, map, 1, 0, true);
    const TileMapId later = createTileMap(world, {.x = 10, .tile = 1, .rows = {"#"}});
    world.restore(saved);
    EXPECT_TRUE(world.isValid(map));
    EXPECT_FALSE(world.isValid(later));
    EXPECT_FALSE(isSolid(world, map, 1, 0));
    EXPECT_EQ(world.snapshot(), saved);
    for (BodyId body : tileMapBodies(world, map))
        EXPECT_EQ(tileMapOf(world, body), map);
}

// --- Refusals ---------------------------------------------------------------------------------

/// A world with a little of everything, for the refusals.
World smallWorld() {
    World world(WorldDef{.gravity = {0, 10}});
    createTileMap(world, {.tile = 1, .rows = {"#./.#", "#####"}});
    world.createBody({.x = 1.5f, .y = -2, .hw = 0.4f, .hh = 0.4f});
    world.createBody({.x = 3.5f, .y = -2, .hw = 0.4f, .hh = 0.4f, .radius = 0.2f});
    for (int step = 0; step < 30; ++step)
        world.step(kDt);
    return world;
}

std::string refusalOf(World& world, const Bytes& bytes) {
    try {
        world.restore(bytes);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

/// `bytes` with its payload's checksum made to match again.
Bytes withChecksum(Bytes bytes) {
    const std::uint64_t sum = snapshot::xxHash64(
        reinterpret_cast<const std::uint8_t*>(bytes.data()) + 32, bytes.size() - 32);
    for (int i = 0; i < 8; ++i)
        bytes[24 + static_cast<std::size_t>(i)] = static_cast<std::byte>(sum >> (8 * i));
    return bytes;
}

TEST(Snapshots, BytesThatAreNotASnapshotAreRefusedByName) {
    World world = smallWorld();
    const Bytes saved = world.snapshot();
    EXPECT_EQ(refusalOf(world, Bytes(10)), "restore: not a jostle snapshot");
    Bytes other = saved;
    other[8] = std::byte{3};
    EXPECT_EQ(refusalOf(world, other), "restore: snapshot format 3, this library reads format 2");
    Bytes cut(saved.begin(), saved.end() - 1);
    EXPECT_EQ(refusalOf(world, cut), "restore: truncated snapshot: " + std::to_string(cut.size()) +
                                         " bytes, its header says " + std::to_string(saved.size()));
    Bytes flipped = saved;
    flipped[saved.size() / 2] ^= std::byte{1};
    EXPECT_EQ(refusalOf(world, flipped),
              "restore: the snapshot is corrupted (its checksum does not match)");
    Bytes small(3);
    EXPECT_NE(refusalOf(world, small), "");
    EXPECT_THROW((void)world.snapshot(std::span<std::byte>(small)), Error);
    EXPECT_EQ(world.snapshot(), saved); // nothing changed
}

TEST(Snapshots, EveryPrefixAndEveryCorruptedByteIsRefusedAndChangesNothing) {
    World world = smallWorld();
    const Bytes saved = world.snapshot();
    for (std::size_t n = 0; n < saved.size(); ++n)
        ASSERT_NE(
            refusalOf(world, Bytes(saved.begin(), saved.begin() + static_cast<std::ptrdiff_t>(n))),
            "")
            << n << " bytes";
    // Past the checksum: each payload byte changed, the checksum made to match again. The
    // reader refuses what it can tell is wrong; what it takes is a world it can step.
    int refused = 0;
    for (std::size_t at = 32; at < saved.size(); ++at)
        for (int flip : {0x01, 0x80, 0xFF}) {
            Bytes bad = saved;
            bad[at] ^= static_cast<std::byte>(flip);
            World target = smallWorld();
            const std::string refusal = refusalOf(target, withChecksum(bad));
            if (refusal.empty()) {
                for (int step = 0; step < 5; ++step)
                    target.step(kDt);
            } else {
                ++refused;
                ASSERT_EQ(refusal.rfind("restore: the snapshot is corrupted: ", 0), 0u) << refusal;
                ASSERT_EQ(target.snapshot(), saved) << "refused, yet changed: " << refusal;
            }
        }
    EXPECT_GT(refused, 0);
}

// fuzz_restore's first campaign found a snapshot whose sleeping body was listed in no
// island: waking its island left it asleep, and the pair search went round forever.
TEST(Snapshots, FuzzTimeout_ASleeperMissingFromItsIslandIsRefused) {
    // Two boxes asleep on floors far apart: two islands of one body each, saved as
    // 'I', 2 islands, [1 body: slot 1], [1 body: slot 3], no free island, then 'C'.
    World world(WorldDef{.gravity = {0, 600}});
    for (float x : {0.0f, 1000.0f}) {
        world.createBody({.type = BodyType::Static, .x = x, .y = 10, .hw = 50, .hh = 10});
        world.createBody({.x = x, .y = -5, .hw = 5, .hh = 5});
    }
    for (int step = 0; step < 240; ++step)
        world.step(kDt);
    ASSERT_FALSE(world.isAwake(world.bodies()[1]));
    ASSERT_FALSE(world.isAwake(world.bodies()[3]));
    const Bytes saved = world.snapshot();
    const std::vector<int> islands{'I', 2, 1, -1, 1, -1, 0, 'C'};
    std::size_t at = 32;
    auto matches = [&](std::size_t k) {
        for (std::size_t i = 0; i < islands.size(); ++i)
            if (islands[i] >= 0 && std::to_integer<int>(saved[k + i]) != islands[i])
                return false;
        return true;
    };
    while (at + islands.size() <= saved.size() && !matches(at))
        ++at;
    ASSERT_LE(at + islands.size(), saved.size()) << "the islands' section not found";
    const std::byte first = saved[at + 3], second = saved[at + 5];
    ASSERT_NE(first, second);

    Bytes swapped = saved; // each body listed in the other's island
    swapped[at + 3] = second;
    swapped[at + 5] = first;
    Bytes missing = saved; // one body listed twice, the other in no island
    missing[at + 5] = first;
    for (const Bytes& bad : {withChecksum(swapped), withChecksum(missing)}) {
        World target = smallWorld();
        const Bytes before = target.snapshot();
        EXPECT_EQ(refusalOf(target, bad), "restore: the snapshot is corrupted: an island's bodies");
        EXPECT_EQ(target.snapshot(), before);
    }
    World again = smallWorld();
    EXPECT_EQ(refusalOf(again, withChecksum(saved)), "");
}

/// Where the four bytes of `impulse` (little-endian) lie in `saved`, after section 'C':
/// the place of a cached contact's impulse in a snapshot of a world with one contact.
std::size_t placeOfCachedImpulse(const Bytes& saved, float impulse) {
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(impulse);
    std::size_t at = 32;
    while (at < saved.size() && std::to_integer<char>(saved[at]) != 'C')
        ++at;
    auto holdsBits = [&](std::size_t k) {
        for (int i = 0; i < 4; ++i)
            if (std::to_integer<std::uint32_t>(saved[k + std::size_t(i)]) !=
                ((bits >> (8 * i)) & 0xFF))
                return false;
        return true;
    };
    while (at + 4 <= saved.size() && !holdsBits(at))
        ++at;
    return at + 4 <= saved.size() ? at : saved.size();
}

/// A box of `hw` × 5 resting on a floor, and the impulse its contact with the floor cached.
std::pair<World, float> boxRestingOnAFloor(float hw) {
    World world(WorldDef{.gravity = {0, 600}});
    world.createBody({.type = BodyType::Static, .y = 10, .hw = 50, .hh = 10});
    const BodyId box = world.createBody({.y = -5, .hw = hw, .hh = 5});
    for (int step = 0; step < 10; ++step)
        world.step(kDt);
    const CachedContact* cached = WorldAccess::state(world).contactCache.find(0, box.index);
    return {std::move(world), cached != nullptr ? cached->normalImpulse : 0.0f};
}

TEST(Snapshots, FuzzNaN_ANegativeCachedNormalImpulseIsRefused) {
    // fuzz_restore: a cached normal impulse of -6e34 was taken, and its warm start flung
    // a sliver of a box to an infinite speed in the next step (NaN). A normal impulse only
    // pushes, so a step never keeps a negative one: such bytes are no snapshot.
    auto [world, impulse] = boxRestingOnAFloor(5);
    ASSERT_GT(impulse, 0.0f); // holds the box up: its weight over a step
    const Bytes saved = world.snapshot();
    const std::size_t at = placeOfCachedImpulse(saved, impulse);
    ASSERT_LT(at, saved.size()) << "the cached impulse not found";
    Bytes negative = saved;
    negative[at + 3] |= std::byte{0x80}; // the sign bit
    World target = smallWorld();
    const Bytes before = target.snapshot();
    EXPECT_EQ(refusalOf(target, withChecksum(negative)),
              "restore: the snapshot is corrupted: a cached contact's impulses");
    EXPECT_EQ(target.snapshot(), before);
    EXPECT_EQ(refusalOf(target, withChecksum(saved)), "");
}

TEST(Snapshots, FuzzNaN_AHugeCachedImpulseOnASliverStepsToFiniteNumbers) {
    // fuzz_restore (huge-cached-impulse): a cached normal impulse of 6e34 under a sliver of
    // a box (1e-5 wide, 10 high: its inverse mass 1e4) flung it to an infinite speed in the
    // next step's warm start, then NaN. A warm start takes of a cached impulse at most what
    // changes a velocity by 1e18 (kMaxMagnitude squared): 1e14 here.
    auto [world, impulse] = boxRestingOnAFloor(5e-6f);
    ASSERT_GT(impulse, 0.0f);
    const Bytes saved = world.snapshot();
    const std::size_t at = placeOfCachedImpulse(saved, impulse);
    ASSERT_LT(at, saved.size()) << "the cached impulse not found";
    Bytes huge = saved;
    const auto bits = std::bit_cast<std::uint32_t>(6e34f);
    for (std::size_t i = 0; i < 4; ++i)
        huge[at + i] = static_cast<std::byte>(bits >> (8 * i));
    World target;
    ASSERT_EQ(refusalOf(target, withChecksum(huge)), "");
    const BodyId box = target.bodies()[1];
    for (int step = 0; step < 10; ++step) {
        target.step(kDt);
        const Body& body = WorldAccess::state(target).slots[box.index];
        ASSERT_TRUE(inRange(body.position) && inRange(body.velocity) && isFinite(body.separation))
            << "step " << step;
    }
    // And the first velocity pass takes back what the warm start gave beyond what holds the
    // box up (a cached normal impulse may fall to 0 within a step): it rests where it was.
    EXPECT_NEAR(target.position(box).y, -5.0f, 0.01f);
}

/// What reading a tile map's list of bodies from `bytes` refuses ("" if nothing).
std::string listRefusal(const std::vector<std::uint8_t>& bytes) {
    ListedBodies list;
    snapshot::Reader reader(bytes);
    try {
        snapshot::Access::listedBodies(reader, list, 1, 10);
    } catch (const snapshot::Refused& refused) {
        return refused.what;
    }
    return "";
}

// fuzz_restore's second campaign: a map's list of bodies claimed 2^32 - 1 tickets, and
// the reader made room for them (16 GB) before reading any.
TEST(Snapshots, FuzzOutOfMemory_TicketsBeyondTheBytesThatFollowAreRefused) {
    // No bodies; tickets 0xFFFFFFFF (LEB128); no free tickets.
    EXPECT_EQ(listRefusal({0, 0xFF, 0xFF, 0xFF, 0xFF, 0x0F, 0}), "a tile map's bodies");
    // Every ticket must be a body's or free: two tickets, one listed free.
    EXPECT_EQ(listRefusal({0, 2, 1, 0}), "a tile map's free tickets");
    EXPECT_EQ(listRefusal({0, 2, 2, 0, 0}), "a tile map's free tickets"); // free twice
    EXPECT_EQ(listRefusal({0, 2, 2, 1, 0}), "");
}

// --- Sizes ----------------------------------------------------------------------------------

TEST(Snapshots, APileTakesAtMost128BytesABodyAnd32AContact) {
    // A 40 × 25 pile on a floor: the issue's budget, counting only the pairs that touch
    // (the cache holds those and the pairs about to).
    World world(WorldDef{.gravity = {0, 600}});
    world.createBody({.type = BodyType::Static, .y = 10, .hw = 500, .hh = 10});
    for (int row = 0; row < 25; ++row)
        for (int i = 0; i < 40; ++i)
            world.createBody({.x = -200.0f + 10.0f * float(i),
                              .y = -5.0f - 10.0f * float(row),
                              .hw = 5,
                              .hh = 5,
                              .friction = 0.6f});
    for (int step = 0; step < 30; ++step)
        world.step(kDt);
    std::size_t touching = 0;
    for (BodyId id : world.bodies())
        touching += world.contacts(id).size();
    touching /= 2;
    EXPECT_GT(touching, 1900u); // each box on two below, or on the floor
    EXPECT_LE(world.snapshotSize(), 128u * 1000u + 32u * touching);
}

TEST(Snapshots, ARunOfBodiesWithTheSameSettingsSavesThemOnce) {
    // Format 2 (docs/snapshots.md): a body whose settings are the body before it's says so
    // in its flags byte instead of writing them. 100 boxes side by side, asleep nowhere and
    // touching nothing, with hw, hh, bounce and friction off their defaults: alike, the
    // settings are written once; each with its own friction, 100 times, each time at least
    // the four floats (16 bytes) and the byte of bits saying which fields follow.
    auto row = [](bool alike) {
        World world(WorldDef{.gravity = {0, 0}});
        for (int i = 0; i < 100; ++i)
            world.createBody({.x = 10.0f * float(i),
                              .hw = 2,
                              .hh = 3,
                              .bounce = 0.5f,
                              .friction = alike ? 0.25f : 0.25f + 0.001f * float(i)});
        return world;
    };
    const World alike = row(true), distinct = row(false);
    const std::size_t saved = distinct.snapshotSize() - alike.snapshotSize();
    EXPECT_GE(saved, 99u * 17u);

    // And each comes back with its own settings.
    World restored;
    restored.restore(alike.snapshot());
    EXPECT_EQ(restored.stateHash(), alike.stateHash());
    for (BodyId id : restored.bodies()) {
        const BodyDef def = restored.bodyDef(id);
        EXPECT_EQ(def.hw, 2.0f);
        EXPECT_EQ(def.hh, 3.0f);
        EXPECT_EQ(def.bounce, 0.5f);
        EXPECT_EQ(def.friction, 0.25f);
    }
    restored.restore(distinct.snapshot());
    const std::span<const BodyId> bodies = restored.bodies();
    for (std::size_t i = 0; i < bodies.size(); ++i)
        EXPECT_EQ(restored.bodyDef(bodies[i]).friction, 0.25f + 0.001f * float(i));
}

} // namespace

TEST(Snapshots, EachCallIsRefusedFromACallbackUnderItsOwnName) {
    // The vector form of snapshot() asked snapshotSize() first, whose name the refusal bore.
    World world = boxRestingOnAFloor(5).first; // named, not a binding: lambdas capture it
    std::vector<std::string> refusals;
    world.setPreSolve([&](Collision&) {
        const std::function<void()> calls[] = {
            [&] { (void)world.snapshot(); },
            [&] { (void)world.snapshotSize(); },
            [&] { (void)world.stateHash(); },
            [&] { world.restore(world.snapshot()); },
        };
        for (const auto& call : calls) {
            try {
                call();
            } catch (const Error& e) {
                refusals.emplace_back(e.what());
            }
        }
        return true;
    });
    world.step(kDt);
    ASSERT_GE(refusals.size(), 4u);
    EXPECT_EQ(refusals[0], "snapshot: called from a callback during step()");
    EXPECT_EQ(refusals[1], "snapshotSize: called from a callback during step()");
    EXPECT_EQ(refusals[2], "stateHash: called from a callback during step()");
    EXPECT_EQ(refusals[3], "snapshot: called from a callback during step()");
}

TEST(Snapshots, AWorldRestoredFromAnotherAdoptsItsHandles) {
    // A saved game loaded by a new run: the game's handles are of the world that saved it
    // (refused as "BodyId of another world"); adopted, they name the same bodies here.
    World saved(WorldDef{.gravity = {0, 10}});
    const TileMapId map = createTileMap(saved, {.tile = 1, .rows = {"####"}});
    const BodyId crate = saved.createBody({.x = 2, .y = -5, .hw = 0.5f, .hh = 0.5f});
    const BodyId gone = saved.createBody({.x = 3, .y = -5, .hw = 0.5f, .hh = 0.5f});
    const std::vector<std::byte> bytes = saved.snapshot();
    saved.destroyBody(gone);

    World loaded;
    loaded.restore(bytes);
    EXPECT_FALSE(loaded.isValid(crate));
    const BodyId adopted = loaded.adopt(crate);
    ASSERT_TRUE(loaded.isValid(adopted));
    EXPECT_EQ(loaded.position(adopted), saved.position(crate));
    EXPECT_EQ(adopted.index, crate.index);
    EXPECT_EQ(adopted.generation, crate.generation);
    EXPECT_TRUE(loaded.isValid(loaded.adopt(BodyId{crate.index, crate.generation}))); // as numbers
    EXPECT_TRUE(loaded.isValid(loaded.adopt(gone))); // alive in the snapshot
    EXPECT_TRUE(loaded.adopt(BodyId{crate.index, crate.generation + 1}).isNull()); // none such
    EXPECT_TRUE(loaded.adopt(BodyId{}).isNull());
    EXPECT_TRUE(loaded.isValid(loaded.adopt(map)));
    EXPECT_TRUE(loaded.adopt(TileMapId{map.index, map.generation + 1}).isNull());
    EXPECT_EQ(saved.adopt(crate), crate); // a world's own handle is its own
}
