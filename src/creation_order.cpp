// Closing the gaps that destroyed bodies leave in the creation order (creation_order.hpp).
#include "creation_order.hpp"

namespace jostle {

void CreationOrder::close() const {
    std::size_t kept = 0;
    for (const BodyId id : entries_)
        if (!id.isNull()) {
            positions_[id.index] = static_cast<std::uint32_t>(kept);
            entries_[kept++] = id;
        }
    entries_.resize(kept);
    gaps_.store(0, std::memory_order_release);
}

void CreationOrder::closeUnderLock() const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (gaps_.load(std::memory_order_relaxed) != 0)
        close();
}

} // namespace jostle
