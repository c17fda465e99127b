// Keeping the touching pairs from the contact events: see contact_set.hpp.
#include "contact_set.hpp"

namespace jostle::demo {

void ContactSet::update(const World& world) {
    // A pair ends and begins in different steps, never in the same one, so the order of
    // these two loops does not matter.
    for (const ContactEvent& event : world.contactEnds())
        pairs_.erase(keyOf(event));
    for (const ContactEvent& event : world.contactBegins())
        pairs_[keyOf(event)] = {event.a, event.b, event.normal};
    // The world ends the pairs of a destroyed body itself (docs/events.md); this is in
    // case one was missed, so that the set cannot fill up with dead pairs over a long run.
    std::erase_if(pairs_, [&world](const auto& entry) {
        return !world.isValid(entry.second.a) || !world.isValid(entry.second.b);
    });
}

std::size_t ContactSet::count(const World& world) const {
    std::size_t pairs = 0;
    forEach(world, [&pairs](const TouchingPair&) { ++pairs; });
    return pairs;
}

} // namespace jostle::demo
