#include "events.hpp"

#include "world_state.hpp"

#include <algorithm>

namespace jostle {

namespace {

/// A pair the step did not look at: neither body is an awake dynamic body.
bool notEvaluated(const WorldState& world, const TouchRecord& record) {
    auto resting = [&](BodyId id) {
        const Body& body = world.slots[id.index];
        return !body.isDynamic() || body.asleep;
    };
    return world.isCurrent(record.a) && world.isCurrent(record.b) && resting(record.a) &&
           resting(record.b);
}

/// Sorts `now` by pair, adds the carried-over pairs of `before`, then reports the pairs
/// only in `now` (begin) and only in `before` (end). `now` becomes the new `before`.
template <class OnBegin, class OnEnd>
void compare(const WorldState& world, std::vector<TouchRecord>& now,
             std::vector<TouchRecord>& before, OnBegin&& begin, OnEnd&& end) {
    for (const TouchRecord& record : before)
        if (notEvaluated(world, record))
            now.push_back(record);
    auto byPair = [](const TouchRecord& p, const TouchRecord& q) {
        return p.key() != q.key() ? p.key() < q.key()
                                  : std::pair(p.a.generation, p.b.generation) <
                                        std::pair(q.a.generation, q.b.generation);
    };
    std::sort(now.begin(), now.end(), byPair);
    // A pair is evaluated once a step, but a carried pair may also have been found again.
    now.erase(std::unique(now.begin(), now.end(),
                          [](const TouchRecord& p, const TouchRecord& q) {
                              return p.a == q.a && p.b == q.b;
                          }),
              now.end());
    std::size_t i = 0, j = 0;
    while (i < now.size() || j < before.size()) {
        if (j == before.size() || (i < now.size() && byPair(now[i], before[j]))) {
            begin(now[i++]);
        } else if (i == now.size() || byPair(before[j], now[i])) {
            end(before[j++]);
        } else {
            ++i;
            ++j;
        }
    }
    before.swap(now);
    now.clear();
}

} // namespace

void recordContact(WorldState& world, std::uint32_t body, std::uint32_t other, Vec2 normal,
                   float approachSpeed) {
    StepEvents& events = world.events;
    // "Down" is where gravity pulls; with none, the screen's down (y grows downward).
    const Vec2 g = world.def.gravity;
    const Vec2 down = g == Vec2{} ? Vec2{0.0f, 1.0f} : g * (1.0f / length(g));
    const Vec2 right{down.y, -down.x};
    auto flag = [&](std::uint32_t slot, Vec2 push) {
        // `push`: the direction the surface pushes the body.
        const float vertical = dot(push, down);
        std::uint8_t bit;
        if (vertical < -0.5f)
            bit = kFloor;
        else if (vertical > 0.5f)
            bit = kCeiling;
        else
            bit = dot(push, right) < 0.0f ? kWallRight : kWallLeft;
        events.touching[slot] |= bit;
    };
    flag(body, normal);
    flag(other, -normal);
    // Listed with the body created first as `a`, the normal pointing towards it.
    if (world.rank[body] < world.rank[other])
        events.contactsNow.push_back({world.idOf(body), world.idOf(other), normal, approachSpeed});
    else
        events.contactsNow.push_back({world.idOf(other), world.idOf(body), -normal, approachSpeed});
}

void recordSensor(WorldState& world, std::uint32_t sensor, std::uint32_t visitor) {
    world.events.sensorsNow.push_back({world.idOf(sensor), world.idOf(visitor), {}, 0.0f});
}

void StepEvents::beginStep(const WorldState& world) {
    begins.clear();
    ends.clear();
    sensorBegins.clear();
    sensorEnds.clear();
    crushes.clear();
    contactsNow.clear();
    sensorsNow.clear();
    touching.resize(world.slots.size(), 0);
    // Awake dynamic bodies are evaluated afresh; the others keep their flags.
    for (BodyId id : world.order) {
        const Body& body = world.slots[id.index];
        if (body.isDynamic() && !body.asleep)
            touching[id.index] = 0;
    }
}

void StepEvents::publish(const WorldState& world) {
    compare(
        world, contactsNow, contactsBefore_,
        [&](const TouchRecord& r) {
            begins.push_back({r.a, r.b, r.normal, r.approachSpeed});
        },
        [&](const TouchRecord& r) {
            ends.push_back({r.a, r.b, r.normal, 0.0f});
        });
    compare(
        world, sensorsNow, sensorsBefore_,
        [&](const TouchRecord& r) {
            sensorBegins.push_back({r.a, r.b});
        },
        [&](const TouchRecord& r) {
            sensorEnds.push_back({r.a, r.b});
        });
}

void StepEvents::clear() {
    *this = StepEvents{};
}

} // namespace jostle
