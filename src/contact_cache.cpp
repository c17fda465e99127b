#include "physical_state.hpp"

namespace jostle {

void ContactCache::clear() {
    offsets_.clear();
    entries_.clear();
    staged_.clear();
}

void ContactCache::stage(std::uint32_t a, std::uint32_t b, const CachedContact& contact) {
    staged_.push_back({a, b, contact});
}

void ContactCache::commit(std::size_t slotCount) {
    offsets_.assign(slotCount + 1, 0);
    for (const Entry& entry : staged_)
        ++offsets_[entry.a + 1];
    for (std::size_t i = 0; i < slotCount; ++i)
        offsets_[i + 1] += offsets_[i];
    entries_.resize(staged_.size());
    // offsets_[a] walks forward while filling; afterwards it holds the end of a's run,
    // which is the start of a + 1's: shift back by one to restore the starts.
    for (const Entry& entry : staged_)
        entries_[offsets_[entry.a]++] = entry;
    for (std::size_t i = slotCount; i > 0; --i)
        offsets_[i] = offsets_[i - 1];
    offsets_[0] = 0;
    staged_.clear();
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
