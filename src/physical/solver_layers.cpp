// Solver layers (solver_layers.hpp).
#include "solver_layers.hpp"

#include "step_context.hpp"

#include <algorithm>

namespace jostle {

void layerContacts(StepContext& step) {
    SolverLayers& layers = step.scratch.layers;
    layers.active = false;
    const auto count = std::uint32_t(step.contacts.size());
    const std::uint32_t block = step.world.tasks->blockSize(kContactsPerBlock);
    if (!step.world.tasks->sharing() || count < 2 * block)
        return;
    // The support levels bound the layers from below: where even that many would be too
    // narrow (below), the layers are not worked out.
    if (count / std::max(step.scratch.support.top, 1u) < kBlocksPerLayer * block)
        return;
    // Layers found too narrow are looked for again only every kStepsBetweenNarrowLooks
    // steps: a world's layers change slowly, and working them out costs.
    if (layers.stepsToNextLook > 0) {
        --layers.stepsToNextLook;
        return;
    }
    // Each contact's layer, kept in `order` for now; `next` holds each body's next layer.
    layers.next.assign(step.bodies.size(), 0);
    layers.layerOf.resize(count);
    std::uint32_t depth = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
        const Contact& c = step.contacts[k];
        std::uint32_t layer = 0;
        if (step.invMassA(c) > 0.0f)
            layer = layers.next[c.ia];
        if (step.invMassB(c) > 0.0f)
            layer = std::max(layer, layers.next[c.ib]);
        if (step.invMassA(c) > 0.0f)
            layers.next[c.ia] = layer + 1;
        if (step.invMassB(c) > 0.0f)
            layers.next[c.ib] = layer + 1;
        layers.layerOf[k] = layer;
        depth = std::max(depth, layer + 1);
    }
    // Narrow layers cost more in handing out and in cache lines passed between cores than
    // they save: many_pyramids_200 (29,000 contacts, 36 layers, three blocks a layer on
    // average) stepped 0.7 to 0.8 times as fast on two workers as on one (docs/threads.md).
    if (count / depth < kBlocksPerLayer * block) {
        layers.stepsToNextLook = kStepsBetweenNarrowLooks - 1;
        return;
    }
    // A counting sort of the contacts by layer, each layer in contact order.
    layers.starts.assign(depth + 1, 0);
    for (std::uint32_t k = 0; k < count; ++k)
        ++layers.starts[layers.layerOf[k] + 1];
    for (std::uint32_t layer = 0; layer < depth; ++layer)
        layers.starts[layer + 1] += layers.starts[layer];
    std::vector<std::uint32_t>& place = layers.next; // reused: each layer's next place
    place.assign(layers.starts.begin(), layers.starts.end() - 1);
    layers.order.resize(count);
    for (std::uint32_t k = 0; k < count; ++k)
        layers.order[place[layers.layerOf[k]]++] = k;
    layers.active = true;
}

} // namespace jostle
