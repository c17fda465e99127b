#include "physical_state.hpp"

namespace jostle {

void ContactCache::clear() {
    offsets_.clear();
    entries_.clear();
}

void ContactCache::beginRebuild(std::size_t slotCount) {
    offsets_.assign(slotCount + 1, 0);
}

void ContactCache::endCounting() {
    const std::size_t slotCount = offsets_.size() - 1;
    for (std::size_t i = 0; i < slotCount; ++i)
        offsets_[i + 1] += offsets_[i];
    entries_.resize(offsets_[slotCount]);
}

void ContactCache::add(std::uint32_t a, std::uint32_t b, const CachedContact& contact) {
    // offsets_[a] walks forward while filling; endRebuild() puts the starts back.
    entries_[offsets_[a]++] = {b, contact};
}

void ContactCache::endRebuild() {
    // Each offsets_[a] now holds the end of a's run, which is the start of a + 1's:
    // shift back by one.
    for (std::size_t i = offsets_.size() - 1; i > 0; --i)
        offsets_[i] = offsets_[i - 1];
    offsets_[0] = 0;
}

const CachedContact* ContactCache::find(std::uint32_t a, std::uint32_t b) const {
    if (std::size_t(a) + 1 >= offsets_.size())
        return nullptr;
    for (std::uint32_t k = offsets_[a]; k < offsets_[a + 1]; ++k)
        if (entries_[k].b == b)
            return &entries_[k].contact;
    return nullptr;
}

} // namespace jostle
