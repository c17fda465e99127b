// Quality figures: top drift, deepest overlap, escaped bodies.
#include "quality.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace jostle::shared {

bool isTopBody(const SceneBody& body) {
    const std::string_view id = body.id;
    return id == "top" || id.starts_with("top.");
}

Bounds sceneBounds(const Scene& scene) {
    constexpr float kHuge = std::numeric_limits<float>::max();
    Bounds bounds{{kHuge, kHuge}, {-kHuge, -kHuge}};
    for (const SceneBody& body : scene.bodies) {
        const BodyDef& d = body.def;
        bounds.min.x = std::min(bounds.min.x, d.x - d.hw);
        bounds.min.y = std::min(bounds.min.y, d.y - d.hh);
        bounds.max.x = std::max(bounds.max.x, d.x + d.hw);
        bounds.max.y = std::max(bounds.max.y, d.y + d.hh);
    }
    const float margin =
        0.05f * std::max(bounds.max.x - bounds.min.x, bounds.max.y - bounds.min.y) + 1.0f;
    bounds.min -= Vec2{margin, margin};
    bounds.max += Vec2{margin, margin};
    return bounds;
}

float maxPenetration(const Scene& scene, std::span<const Vec2> positions) {
    float cell = 0.0f;
    for (const SceneBody& body : scene.bodies)
        if (body.def.type == BodyType::Dynamic)
            cell = std::max({cell, 2.0f * body.def.hw, 2.0f * body.def.hh});
    if (cell == 0.0f)
        return 0.0f;

    // Every body inside the bounds goes into each grid cell its box covers; a pair that
    // overlaps shares at least one cell. Bodies outside are counted as escaped instead,
    // and keeping them out keeps cell coordinates small.
    const Bounds bounds = sceneBounds(scene);
    struct Entry {
        std::uint64_t cell;
        std::uint32_t body;
        auto operator<=>(const Entry&) const = default;
    };
    std::vector<Entry> entries;
    entries.reserve(positions.size() * 2);
    const auto cellOf = [&](float v, float origin) {
        return static_cast<std::uint32_t>(std::floor((v - origin) / cell));
    };
    for (std::size_t i = 0; i < scene.bodies.size() && i < positions.size(); ++i) {
        const Vec2 p = positions[i];
        if (!isFinite(p) || !bounds.contains(p))
            continue;
        const BodyDef& d = scene.bodies[i].def;
        // Boxes may stick out of the bounds by their half extents: clamp to them.
        const float x0 = std::clamp(p.x - d.hw, bounds.min.x, bounds.max.x);
        const float x1 = std::clamp(p.x + d.hw, bounds.min.x, bounds.max.x);
        const float y0 = std::clamp(p.y - d.hh, bounds.min.y, bounds.max.y);
        const float y1 = std::clamp(p.y + d.hh, bounds.min.y, bounds.max.y);
        for (std::uint32_t cx = cellOf(x0, bounds.min.x); cx <= cellOf(x1, bounds.min.x); ++cx)
            for (std::uint32_t cy = cellOf(y0, bounds.min.y); cy <= cellOf(y1, bounds.min.y); ++cy)
                entries.push_back({(std::uint64_t{cx} << 32) | cy, static_cast<std::uint32_t>(i)});
    }
    std::sort(entries.begin(), entries.end());

    // A pair sharing several cells is tested in each: harmless, the maximum is the same.
    float deepest = 0.0f;
    for (std::size_t first = 0; first < entries.size();) {
        std::size_t last = first + 1;
        while (last < entries.size() && entries[last].cell == entries[first].cell)
            ++last;
        for (std::size_t a = first; a < last; ++a)
            for (std::size_t b = a + 1; b < last; ++b) {
                const BodyDef& da = scene.bodies[entries[a].body].def;
                const BodyDef& db = scene.bodies[entries[b].body].def;
                if (da.type != BodyType::Dynamic && db.type != BodyType::Dynamic)
                    continue;
                const Vec2 pa = positions[entries[a].body];
                const Vec2 pb = positions[entries[b].body];
                const float ox = da.hw + db.hw - std::abs(pa.x - pb.x);
                const float oy = da.hh + db.hh - std::abs(pa.y - pb.y);
                if (ox > 0.0f && oy > 0.0f)
                    deepest = std::max(deepest, std::min(ox, oy));
            }
        first = last;
    }
    return deepest;
}

Quality measureQuality(const Scene& scene, std::span<const Vec2> positions) {
    Quality quality;
    const Bounds bounds = sceneBounds(scene);
    for (std::size_t i = 0; i < scene.bodies.size() && i < positions.size(); ++i) {
        const SceneBody& body = scene.bodies[i];
        const Vec2 p = positions[i];
        if (body.def.type == BodyType::Dynamic && !(isFinite(p) && bounds.contains(p)))
            ++quality.escaped;
        if (isTopBody(body)) {
            float drift = length(p - Vec2{body.def.x, body.def.y});
            if (!std::isfinite(drift)) // lost altogether: worse than any finite drift
                drift = std::numeric_limits<float>::infinity();
            quality.topDrift = std::max(quality.topDrift.value_or(0.0f), drift);
        }
    }
    quality.maxPenetration = maxPenetration(scene, positions);
    return quality;
}

} // namespace jostle::shared
