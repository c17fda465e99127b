#include "pairs.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

namespace {

struct Extent {
    float minX, maxX, minY, maxY;
    std::uint32_t rank; ///< position in creation order
    std::uint32_t slot;
    bool dynamic;
};

} // namespace

void findPairs(const WorldState& world, float dt, std::vector<BodyPair>& pairs) {
    pairs.clear();
    std::vector<Extent> extents;
    extents.reserve(world.order.size());
    for (std::uint32_t rank = 0; rank < world.order.size(); ++rank) {
        const std::uint32_t slot = world.order[rank].index;
        const Body& body = world.slots[slot];
        const Vec2 reach = {body.half.x + std::abs(body.velocity.x) * dt,
                            body.half.y + std::abs(body.velocity.y) * dt};
        extents.push_back({body.position.x - reach.x, body.position.x + reach.x,
                           body.position.y - reach.y, body.position.y + reach.y, rank, slot,
                           body.isDynamic()});
    }
    // Sort by left edge; ties by creation rank, so the order is total and reproducible.
    std::sort(extents.begin(), extents.end(), [](const Extent& p, const Extent& q) {
        return p.minX < q.minX || (p.minX == q.minX && p.rank < q.rank);
    });

    std::vector<std::pair<std::uint32_t, std::uint32_t>> ranked;
    for (std::size_t i = 0; i < extents.size(); ++i) {
        const Extent& p = extents[i];
        for (std::size_t j = i + 1; j < extents.size() && extents[j].minX <= p.maxX; ++j) {
            const Extent& q = extents[j];
            if (!p.dynamic && !q.dynamic)
                continue;
            if (q.minY > p.maxY || p.minY > q.maxY)
                continue;
            ranked.emplace_back(std::min(p.rank, q.rank), std::max(p.rank, q.rank));
        }
    }
    std::sort(ranked.begin(), ranked.end());
    pairs.reserve(ranked.size());
    for (const auto& [ra, rb] : ranked)
        pairs.push_back({world.order[ra].index, world.order[rb].index});
}

} // namespace jostle
