// The support order. Contacts are solved from the ground up, and in each one body may
// hold the other (it stays put in shock propagation and position correction): the lower
// one along gravity, or, between two dynamic bodies, one with a static or kinematic body
// right behind it. docs/physical-model.md, "Support", says why each rule is there.
#include "support.hpp"

#include "step_context.hpp"

#include <algorithm>
#include <utility>

namespace jostle {

namespace {

constexpr std::uint32_t kUnsupported = UINT32_MAX;
/// Contacts per block of the loop that finds supporters.
constexpr std::uint32_t kSupportersPerBlock = 2048;

/// The contact graph over solver bodies, as runs of neighbours.
void buildGraph(StepContext& step) {
    SupportScratch& s = step.scratch.support;
    s.graph.reset(step.bodies.size());
    for (const Contact& c : step.contacts) {
        s.graph.count(c.ia);
        s.graph.count(c.ib);
    }
    s.neighbours.resize(s.graph.endCounting());
    s.edgeContact.resize(s.neighbours.size());
    for (std::uint32_t k = 0; k < step.contacts.size(); ++k) {
        const Contact& c = step.contacts[k];
        const std::uint32_t toB = s.graph.place(c.ia);
        const std::uint32_t toA = s.graph.place(c.ib);
        s.neighbours[toB] = c.ib;
        s.neighbours[toA] = c.ia;
        s.edgeContact[toB] = k;
        s.edgeContact[toA] = k;
    }
    s.graph.endPlacing();
}

/// Levels by a breadth-first search from the static and kinematic bodies.
void findLevels(StepContext& step) {
    SupportScratch& s = step.scratch.support;
    const std::size_t n = step.bodies.size();
    s.levels.assign(n, kUnsupported);
    s.queue.clear();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (step.bodies[i].invMass == 0.0f) {
            s.levels[i] = 0;
            s.queue.push_back(i);
        }
    }
    for (std::size_t head = 0; head < s.queue.size(); ++head) {
        const std::uint32_t body = s.queue[head];
        for (std::uint32_t k = s.graph.begin(body); k < s.graph.end(body); ++k) {
            const std::uint32_t other = s.neighbours[k];
            if (s.levels[other] == kUnsupported) {
                s.levels[other] = s.levels[body] + 1;
                s.queue.push_back(other);
            }
        }
    }
}

std::uint8_t backingBit(int axis, float direction) {
    return std::uint8_t(1u << (2 * axis + (direction > 0.0f ? 1 : 0)));
}

/// Which solver bodies touch a static or kinematic body, and on which sides. A
/// speculative contact, still apart (its target lets the gap close), is no backing yet.
void findBacking(StepContext& step) {
    std::vector<std::uint8_t>& backing = step.scratch.support.backing;
    backing.assign(step.bodies.size(), 0);
    for (const Contact& c : step.contacts) {
        if (c.targetSpeed < 0.0f || c.axis == kAlongSlope)
            continue;
        // The normal points from b towards a: b lies on a's side -sign, a on b's +sign.
        if (step.invMassB(c) == 0.0f)
            backing[c.ia] |= backingBit(c.axis, -c.sign());
        if (step.invMassA(c) == 0.0f)
            backing[c.ib] |= backingBit(c.axis, c.sign());
    }
}

/// Whether solver body `i` has a static or kinematic body next to it along `axis`, in
/// `direction` (its sign).
bool isBacked(const StepContext& step, std::uint32_t i, int axis, float direction) {
    return (step.scratch.support.backing[i] & backingBit(axis, direction)) != 0;
}

/// Which body of `c` holds the other: 0 none, 1 a, 2 b.
std::uint8_t supporterOf(const StepContext& step, const Contact& c) {
    const std::uint32_t la = step.scratch.support.levels[c.ia];
    const std::uint32_t lb = step.scratch.support.levels[c.ib];
    std::uint8_t supporter = la < lb ? 1 : lb < la ? 2 : 0;
    const Vec2 gravity = step.world.def.gravity;
    if (gravity != Vec2{}) {
        const float down = dot(c.normal(), gravity); // > 0: a is below b
        // Only from below: a body reached through a sideways contact is no floor.
        if ((supporter == 1 && !(down > 0.0f)) || (supporter == 2 && !(down < 0.0f)))
            supporter = 0;
        // Within a level, the lower body of a contact along gravity holds the upper one.
        if (la == lb && la != kUnsupported && down != 0.0f)
            supporter = down > 0.0f ? 1 : 2;
    }
    // Neither holding the other up, between two dynamic bodies: one with a static or
    // kinematic body right behind it, on the side the contact pushes it to.
    if (supporter == 0 && step.invMassA(c) > 0.0f && step.invMassB(c) > 0.0f &&
        c.axis != kAlongSlope) {
        const bool aHeld = isBacked(step, c.ia, c.axis, c.sign());
        const bool bHeld = isBacked(step, c.ib, c.axis, -c.sign());
        supporter = aHeld && !bHeld ? 1 : bHeld && !aHeld ? 2 : 0;
    }
    return supporter;
}

/// A stable counting sort of the contacts by level, unsupported ones (floating piles)
/// last. Contacts are large: the sort finds each one's destination, then moves them there
/// in place, along the cycles of the permutation, each contact copied once (a place takes
/// the contact its source names; the first of a cycle waits aside for the last place).
void sortByLevel(StepContext& step, std::uint32_t top) {
    SupportScratch& s = step.scratch.support;
    auto bucket = [&](const Contact& c) {
        const std::uint32_t level = std::min(s.levels[c.ia], s.levels[c.ib]);
        return level == kUnsupported ? top : level;
    };
    s.byLevel.reset(std::size_t(top) + 1);
    for (const Contact& c : step.contacts)
        s.byLevel.count(bucket(c));
    s.byLevel.endCounting();
    std::vector<Contact>& contacts = step.contacts;
    s.destination.resize(contacts.size());
    for (std::size_t k = 0; k < contacts.size(); ++k)
        s.destination[k] = s.byLevel.place(bucket(contacts[k]));
    s.sortedPlace = s.destination;
    std::vector<std::uint32_t>& source = s.destination; // by place: whose contact goes there
    for (std::uint32_t k = 0; k < contacts.size(); ++k)
        source[s.sortedPlace[k]] = k;
    for (std::uint32_t k = 0; k < contacts.size(); ++k) {
        if (source[k] == k)
            continue; // in its place, or placed
        const Contact first = contacts[k];
        std::uint32_t place = k;
        while (source[place] != k) {
            const std::uint32_t from = source[place];
            contacts[place] = contacts[from];
            source[place] = place;
            place = from;
        }
        contacts[place] = first;
        source[place] = place;
    }
}

} // namespace

void orderBySupport(StepContext& step) {
    buildGraph(step);
    findLevels(step);
    findBacking(step);
    SupportScratch& s = step.scratch.support;
    const auto contacts = std::uint32_t(step.contacts.size());
    TaskRunner& tasks = *step.world.tasks;
    s.topOfBlock.assign(tasks.blocksOf(contacts, kSupportersPerBlock), 0);
    tasks.forEachBlock(contacts, kSupportersPerBlock, [&](Block block) {
        std::uint32_t top = 0;
        for (std::uint32_t k = block.begin; k < block.end; ++k) {
            Contact& c = step.contacts[k];
            c.supporter = supporterOf(step, c);
            const std::uint32_t level = std::min(s.levels[c.ia], s.levels[c.ib]);
            if (level != kUnsupported)
                top = std::max(top, level + 1);
        }
        s.topOfBlock[block.index] = top;
    });
    std::uint32_t top = 0;
    for (std::uint32_t blockTop : s.topOfBlock)
        top = std::max(top, blockTop);
    s.top = top;
    sortByLevel(step, top);
}

bool haveContact(const StepContext& step, std::uint32_t ia, std::uint32_t ib) {
    const SupportScratch& s = step.scratch.support;
    const std::size_t known = s.graph.keyCount();
    if (ia >= known || ib >= known)
        return false;
    for (std::uint32_t k = s.graph.begin(ia); k < s.graph.end(ia); ++k)
        if (s.neighbours[k] == ib)
            return true;
    return false;
}

} // namespace jostle
