// The scene in jostle, exactly as the scene describes it, except for the sleeping switch
// and the worker count.
#include "engine.hpp"
#include "timing.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace jostle::bench {
namespace {

class JostleEngine final : public Engine {
public:
    JostleEngine(const Scene& scene, bool sleeping, int workers)
        : world_(adjusted(scene.world, sleeping, workers)) {
        for (const SceneBody& body : scene.bodies)
            world_.createBody(body.def);
    }

    void step(float dt) override { world_.step(dt); }

    const StepProfile* profile() const override { return &world_.profile(); }

    std::optional<SnapshotFigures> measureSnapshots(int runs) override {
        std::vector<std::byte> saved = world_.snapshot();
        std::vector<std::byte> buffer(saved.size());
        SnapshotFigures figures;
        figures.bytes = saved.size();
        figures.saveMicroseconds = medianMicroseconds(runs, [&] { world_.snapshot(buffer); });
        figures.restoreMicroseconds = medianMicroseconds(runs, [&] { world_.restore(saved); });
        figures.hashMicroseconds =
            medianMicroseconds(runs, [&] { lastHash_ = world_.stateHash(); });
        return figures;
    }

    void positions(std::span<Vec2> out) const override {
        // No body is destroyed, so creation order is scene order.
        const std::span<const BodyId> ids = world_.bodies();
        for (std::size_t i = 0; i < ids.size() && i < out.size(); ++i)
            out[i] = world_.position(ids[i]);
    }

private:
    static WorldDef adjusted(WorldDef def, bool sleeping, int workers) {
        def.sleeping = sleeping;
        def.tasks.workers = workers;
        return def;
    }

    World world_;
    std::uint64_t lastHash_ = 0; ///< the state hash last timed, kept so the call is made
};

} // namespace

std::unique_ptr<Engine> makeJostle(const Scene& scene, bool sleeping, int workers) {
    return std::make_unique<JostleEngine>(scene, sleeping, workers);
}

std::string describeJostle() {
    const PhysicalOptions defaults;
    return "jostle: physical model with its default settings (" +
           std::to_string(defaults.velocityIterations) + " velocity / " +
           std::to_string(defaults.positionIterations) + " position iterations)";
}

} // namespace jostle::bench
