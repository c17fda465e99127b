// How a snapshot saves a body's fields (section B, docs/snapshots.md), in three groups:
// its settings (the rows of kBodyFields but position and velocity), its position (always
// saved), and its state (velocity, and the run-time state steps and setters keep beside
// the settings). Settings and state are saved only where their bits differ from their
// defaults, and a body's settings not at all when they are the body before it's (a pile of
// like boxes). The rows are turned once into plain entries (where the field lies among a
// body's places, how it is encoded, its default's bytes), so that saving a body is a loop
// over them, not a visit per row.
#pragma once

#include "../body_properties.hpp"
#include "../body_state.hpp"
#include "archive.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <type_traits>

namespace jostle::snapshot {

/// Run-time state kept in Body beside the settings: saved after the rows of kBodyFields.
/// (Mass is not: it is worked out again from the settings, as createBody does.)
inline constexpr float Body::*kRunTimeNumbers[] = {&Body::floorCos, &Body::sleepTime,
                                                   &Body::walkSpeed, &Body::dropThroughTime};
inline constexpr Vec2 Body::*kRunTimeVectors[] = {&Body::separation, &Body::lastStepVelocity};

inline constexpr std::size_t kBodyCodecs =
    std::size(properties::kBodyFields) + std::size(kRunTimeNumbers) + std::size(kRunTimeVectors);
static_assert(kBodyCodecs <= 64, "a body's fields fit the 64 bits that say which are saved");

struct FieldCodec {
    enum Kind : std::uint8_t { Skip, Flag, Byte, Number, Vector, Whole };
    enum Group : std::uint8_t { Settings, Position, State };
    Kind kind = Skip;
    Group group = Settings;
    std::uint8_t place = 0; ///< 0: Body, 1: KeptAsGiven, 2: Shape
    std::uint16_t offset = 0;
    std::uint8_t size = 0;
    std::uint8_t byDefault[8] = {};
};

/// A body's places as bytes, in FieldCodec::place's order.
struct PlaceBytes {
    std::uint8_t* at[3];
    explicit PlaceBytes(properties::Places places)
        : at{reinterpret_cast<std::uint8_t*>(&places.body),
             reinterpret_cast<std::uint8_t*>(&places.kept),
             reinterpret_cast<std::uint8_t*>(&places.shape)} {}
    std::uint8_t* of(const FieldCodec& codec) const { return at[codec.place] + codec.offset; }
};

namespace detail {

template <class T>
FieldCodec codecOf(const PlaceBytes& sample, const T& field, const T& byDefault) {
    FieldCodec codec;
    if constexpr (std::is_same_v<T, float>)
        codec.kind = FieldCodec::Number;
    else if constexpr (std::is_same_v<T, Vec2>)
        codec.kind = FieldCodec::Vector;
    else if constexpr (std::is_same_v<T, bool>)
        codec.kind = FieldCodec::Flag;
    else if constexpr (std::is_enum_v<T>)
        codec.kind = FieldCodec::Byte;
    else if constexpr (std::is_same_v<T, std::uint32_t>)
        codec.kind = FieldCodec::Whole;
    else
        return codec; // userData: the program's, never saved
    static_assert(sizeof(T) <= sizeof(FieldCodec::byDefault));
    static_assert(sizeof(T) == 1 || !std::is_enum_v<T>, "enumerations are saved as a byte");
    const auto* address = reinterpret_cast<const std::uint8_t*>(&field);
    for (std::uint8_t place = 0; place < 3; ++place)
        if (address >= sample.at[place] &&
            address < sample.at[place] + (place == 0   ? sizeof(Body)
                                          : place == 1 ? sizeof(KeptAsGiven)
                                                       : sizeof(Shape))) {
            codec.place = place;
            codec.offset = static_cast<std::uint16_t>(address - sample.at[place]);
        }
    codec.size = sizeof(T);
    std::memcpy(codec.byDefault, &byDefault, sizeof(T));
    return codec;
}

inline std::array<FieldCodec, kBodyCodecs> makeBodyCodecs() {
    Body body;
    KeptAsGiven kept;
    Shape shape;
    const properties::Places places{body, kept, shape};
    const PlaceBytes sample(places);
    std::array<FieldCodec, kBodyCodecs> codecs{};
    std::size_t i = 0;
    for (const properties::BodyField& field : properties::kBodyFields) {
        field.visitStore([&](auto member, auto store) {
            using T = std::remove_cvref_t<decltype(BodyDef{}.*member)>;
            codecs[i] =
                codecOf<T>(sample, at(places, store), std::get<T>(field.property->byDefault));
        });
        ++i;
    }
    const Body fresh;
    for (float Body::*number : kRunTimeNumbers)
        codecs[i++] = codecOf<float>(sample, body.*number, fresh.*number);
    for (Vec2 Body::*vector : kRunTimeVectors)
        codecs[i++] = codecOf<Vec2>(sample, body.*vector, fresh.*vector);
    for (std::size_t k = std::size(properties::kBodyFields); k < kBodyCodecs; ++k)
        codecs[k].group = FieldCodec::State;
    auto within = [](const FieldCodec& codec, std::size_t vector) {
        return codec.place == 0 && codec.offset >= vector && codec.offset < vector + sizeof(Vec2);
    };
    for (FieldCodec& codec : codecs)
        if (within(codec, offsetof(Body, position)))
            codec.group = FieldCodec::Position;
        else if (within(codec, offsetof(Body, velocity)))
            codec.group = FieldCodec::State;
    return codecs;
}

} // namespace detail

/// A body made from the default BodyDef, where a world keeps it: what a restored body's
/// fields are before those its snapshot holds are read.
struct DefaultPlaces {
    Body body;
    KeptAsGiven kept;
    Shape shape;
};

inline const DefaultPlaces& defaultPlaces() {
    static const DefaultPlaces defaults = [] {
        DefaultPlaces made;
        properties::keep(BodyDef{}, {made.body, made.kept, made.shape});
        return made;
    }();
    return defaults;
}

/// The codecs of a body's fields, in the order their bits and bytes are saved.
inline const std::array<FieldCodec, kBodyCodecs>& bodyCodecs() {
    static const std::array<FieldCodec, kBodyCodecs> codecs = detail::makeBodyCodecs();
    return codecs;
}

/// Whether the field at `at` has its default's bytes (sizes 1, 4 and 8, compared whole).
inline bool sameBytes(const std::uint8_t* at, const FieldCodec& codec) {
    auto same = [&](auto word) {
        decltype(word) other;
        std::memcpy(&word, at, sizeof word);
        std::memcpy(&other, codec.byDefault, sizeof other);
        return word == other;
    };
    switch (codec.size) {
    case 1:
        return *at == codec.byDefault[0];
    case 4:
        return same(std::uint32_t{});
    default:
        return same(std::uint64_t{});
    }
}

/// The fields of one group, in bodyCodecs()' order.
struct GroupCodecs {
    std::size_t count = 0;
    const FieldCodec* codec[kBodyCodecs] = {};
    /// Every field a float or a vector of them (the state group): read and written without
    /// a switch over the kinds, whose jumps a loop over many bodies mispredicts.
    bool floatsOnly = true;
};

inline const GroupCodecs& groupCodecs(FieldCodec::Group group) {
    static const std::array<GroupCodecs, 3> groups = [] {
        std::array<GroupCodecs, 3> made{};
        for (const FieldCodec& codec : bodyCodecs())
            if (codec.kind != FieldCodec::Skip) {
                GroupCodecs& into = made[codec.group];
                into.codec[into.count++] = &codec;
                into.floatsOnly = into.floatsOnly && (codec.kind == FieldCodec::Number ||
                                                      codec.kind == FieldCodec::Vector);
            }
        return made;
    }();
    return groups[group];
}

/// Whether two bodies' settings (the Settings group) have the same bits: the bytes of each
/// place under a mask of the settings' bytes, compared a word at a time.
class SettingsBytes {
public:
    static const SettingsBytes& get() {
        static const SettingsBytes made;
        return made;
    }
    bool same(const PlaceBytes& a, const PlaceBytes& b) const {
        std::uint64_t differ = 0;
        for (std::size_t place = 0; place < 3; ++place) {
            const std::size_t words = kSizes[place] / 8;
            for (std::size_t w = 0; w < words; ++w) {
                std::uint64_t x, y;
                std::memcpy(&x, a.at[place] + 8 * w, 8);
                std::memcpy(&y, b.at[place] + 8 * w, 8);
                differ |= (x ^ y) & words_[place][w];
            }
            for (std::size_t i = 8 * words; i < kSizes[place]; ++i) // a 32-bit machine's tail
                differ |= std::uint64_t(a.at[place][i] ^ b.at[place][i]) & bytes_[place][i];
        }
        return differ == 0;
    }

private:
    static constexpr std::size_t kSizes[3] = {sizeof(Body), sizeof(KeptAsGiven), sizeof(Shape)};
    static_assert(sizeof(KeptAsGiven) <= sizeof(Body) && sizeof(Shape) <= sizeof(Body));
    SettingsBytes() {
        for (const FieldCodec& codec : bodyCodecs())
            if (codec.kind != FieldCodec::Skip && codec.group == FieldCodec::Settings)
                std::memset(bytes_[codec.place] + codec.offset, 0xFF, codec.size);
        std::memcpy(words_, bytes_, sizeof words_); // the words as the machine orders bytes
    }
    std::uint8_t bytes_[3][sizeof(Body)] = {};
    std::uint64_t words_[3][sizeof(Body) / 8] = {};
};

/// The fields of `group` that differ from their defaults by their bits (archive.hpp's two
/// directions): a `var` whose bit j says the group's j-th field follows, then those fields
/// in order. A reader's body holds the defaults before.
template <class Ar> void groupFields(Ar& ar, const PlaceBytes& body, FieldCodec::Group group) {
    const GroupCodecs& fields = groupCodecs(group);
    std::uint64_t present = 0;
    if constexpr (!Ar::kReading)
        for (std::size_t j = 0; j < fields.count; ++j)
            if (!sameBytes(body.of(*fields.codec[j]), *fields.codec[j]))
                present |= std::uint64_t{1} << j;
    ar.var(present);
    ar.check(present >> fields.count == 0, "a body's fields");
    if (fields.floatsOnly) {
        for (std::uint64_t left = present; left != 0; left &= left - 1) {
            const FieldCodec& codec = *fields.codec[std::countr_zero(left)];
            std::uint8_t* at = body.of(codec);
            if (codec.kind == FieldCodec::Number)
                ar.f32(*reinterpret_cast<float*>(at));
            else
                ar.vec(*reinterpret_cast<Vec2*>(at));
        }
        return;
    }
    for (std::uint64_t left = present; left != 0; left &= left - 1) {
        const FieldCodec& codec = *fields.codec[std::countr_zero(left)];
        std::uint8_t* at = body.of(codec);
        switch (codec.kind) {
        case FieldCodec::Skip: // userData: never saved, and never in a group
            break;
        case FieldCodec::Flag:
            ar.flag(*reinterpret_cast<bool*>(at));
            break;
        case FieldCodec::Byte:
            ar.u8(*at);
            break;
        case FieldCodec::Number:
            ar.f32(*reinterpret_cast<float*>(at));
            break;
        case FieldCodec::Vector:
            ar.vec(*reinterpret_cast<Vec2*>(at));
            break;
        case FieldCodec::Whole:
            ar.var(*reinterpret_cast<std::uint32_t*>(at));
            break;
        }
    }
}

} // namespace jostle::snapshot
