// The C API's events: the last step's arrays, kept in C layout by the C world.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

/// The array and its length, or NULL and 0 on misuse.
template <class Event>
const Event* handOut(const char* function, const jostle_world* world, int* count,
                     std::vector<Event> jostle_world::*events) {
    return guard<const Event*>(function, nullptr, [&]() -> const Event* {
        if (count != nullptr)
            *count = 0;
        const jostle_world& w = worldOf(world);
        required(count, "count");
        const std::vector<Event>& array = w.*events;
        *count = countOf(array.size());
        return array.data();
    });
}

} // namespace

namespace jostle::c_api {

void publishEvents(jostle_world& w) {
    try {
        convert(w.world.contactBegins(), w.contactBegins);
        convert(w.world.contactEnds(), w.contactEnds);
        convert(w.world.sensorBegins(), w.sensorBegins);
        convert(w.world.sensorEnds(), w.sensorEnds);
        convert(w.world.crushBegins(), w.crushBegins);
        convert(w.world.crushEnds(), w.crushEnds);
    } catch (...) {
        // Out of memory: better no events than a mix of two steps'.
        w.contactBegins.clear();
        w.contactEnds.clear();
        w.sensorBegins.clear();
        w.sensorEnds.clear();
        w.crushBegins.clear();
        w.crushEnds.clear();
        throw;
    }
}

} // namespace jostle::c_api

extern "C" {

const jostle_contact_event* jostle_world_contact_begins(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::contactBegins);
}

const jostle_contact_event* jostle_world_contact_ends(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::contactEnds);
}

const jostle_sensor_event* jostle_world_sensor_begins(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::sensorBegins);
}

const jostle_sensor_event* jostle_world_sensor_ends(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::sensorEnds);
}

const jostle_crush_event* jostle_world_crush_begins(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::crushBegins);
}

const jostle_crush_event* jostle_world_crush_ends(const jostle_world* world, int* count) {
    return handOut(__func__, world, count, &jostle_world::crushEnds);
}

uint64_t jostle_world_pairs_left_out(const jostle_world* world) {
    return guard(__func__, std::uint64_t{0}, [&] { return worldOf(world).world.pairsLeftOut(); });
}

jostle_step_profile jostle_world_get_profile(const jostle_world* world) {
    return guard(__func__, jostle_step_profile{}, [&] {
        // The C struct holds StepProfile's floats in its order.
        static_assert(sizeof(jostle_step_profile) == sizeof(StepProfile));
        const StepProfile& p = worldOf(world).world.profile();
        jostle_step_profile out{};
        float* to = &out.step;
        for (std::size_t k = 0; k < std::size(kStepProfileFields); ++k)
            to[k] = p.*kStepProfileFields[k].ms;
        return out;
    });
}

} // extern "C"
