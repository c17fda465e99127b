// Definition tables (world, body, tile map, options) read and given back by the
// descriptions of src/properties.hpp's tables: a field of each type a property has read
// from a Lua table by its name, and pushed back as one Lua value. So newWorld, newBody,
// newTileMap, getDef and the options' getters and setters list no field themselves.
#pragma once

#include "binding.hpp"
#include "properties.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <variant>

namespace jostle::lua {

/// The names Lua and scene files give the values of each enum, in the order of the values,
/// ended by nullptr.
inline constexpr const char* kTypeNames[] = {"static", "kinematic", "dynamic", nullptr};
inline constexpr const char* kSolverNames[] = {"classic", "physical", nullptr};
inline constexpr const char* kFrictionMixNames[] = {"min", "geometricMean", nullptr};
/// The names of an enum's values (kTypeNames...).
template <class E> constexpr const char* const* namesOf();
template <> constexpr const char* const* namesOf<BodyType>() {
    return kTypeNames;
}
template <> constexpr const char* const* namesOf<Solver>() {
    return kSolverNames;
}
template <> constexpr const char* const* namesOf<FrictionMix>() {
    return kFrictionMixNames;
}
/// The value of an enum whose name is at `option` in namesOf<E>().
template <class E> E valueAt(int option) {
    return static_cast<E>(option);
}

/// Reads the field of `property` (by its name) into `out`: true if it is given. Raises if
/// its value has the wrong type, or is a whole number outside the property's interval
/// (Rule::Interval). A float takes math.huge where the rule allows no limit.
bool readField(const Fields& fields, const properties::Property& property, float& out);
bool readField(const Fields& fields, const properties::Property& property, Vec2& out);
bool readField(const Fields& fields, const properties::Property& property, bool& out);
bool readField(const Fields& fields, const properties::Property& property, std::uint32_t& out);
bool readField(const Fields& fields, const properties::Property& property, int& out);
/// A pointer (userData) is any Lua value, which the binding keeps itself: never read here.
bool readField(const Fields& fields, const properties::Property& property, void*& out);
/// An enum's value by its name (namesOf).
template <class E>
requires std::is_enum_v<E>
bool readField(const Fields& fields, const properties::Property& property, E& out) {
    int option = 0;
    if (!fields.option(property.name, option, namesOf<E>()))
        return false;
    out = valueAt<E>(option);
    return true;
}

/// Pushes a value as one Lua value; false (nothing pushed) for a pointer.
bool pushField(lua_State* L, float value);
bool pushField(lua_State* L, Vec2 value);
bool pushField(lua_State* L, bool value);
bool pushField(lua_State* L, std::uint32_t value);
bool pushField(lua_State* L, int value);
bool pushField(lua_State* L, void* pointer);
/// An enum's value as its name (namesOf).
template <class E>
requires std::is_enum_v<E>
bool pushField(lua_State* L, E value) {
    lua_pushstring(L, namesOf<E>()[static_cast<int>(value)]);
    return true;
}

/// True if a Lua table gives the property: all but a pointer, where only a body's is given
/// (as any Lua value: World:newBody keeps it).
inline constexpr bool isPointer(const properties::Property& property) {
    return std::holds_alternative<void*>(property.byDefault);
}

/// A list of field names for Fields::allowOnly, ended by nullptr, built from tables.
template <std::size_t Capacity> struct Names {
    std::array<const char*, Capacity + 1> names{};
    std::size_t count = 0;

    constexpr Names& add(const char* name) {
        names[count++] = name;
        return *this;
    }
    /// Adds the name of each field of `fields`, but pointers unless `pointers`.
    template <class F, std::size_t N>
    constexpr Names& addAll(const F (&fields)[N], bool pointers = false) {
        for (const F& field : fields)
            if (pointers || !isPointer(*field.property))
                add(field.property->name);
        return *this;
    }
    const char* const* data() const { return names.data(); }
};

/// Reads each field of `table` that the Lua table gives into `def`, in table order, then
/// calls after(field, given).
template <class Def, class F, std::size_t N, class After>
void readFields(const Fields& fields, Def& def, const F (&table)[N], After&& after) {
    for (const F& field : table) {
        auto read = [&](auto member) { return readField(fields, *field.property, def.*member); };
        after(field, std::visit(read, field.member));
    }
}

/// Reads each option of `table` the Lua table gives into `def`, each checked by its rule as
/// it is read ("physical.slop: must be in [0, 0.5]").
template <class Def, class F, std::size_t N>
void readOptions(const Fields& fields, Def& def, const F (&table)[N]) {
    for (const F& field : table)
        std::visit(
            [&](auto member) {
                const properties::Property& property = *field.property;
                if (readField(fields, property, def.*member))
                    if (const char* problem = properties::problemOf(property, def.*member))
                        fields.fail(property.name, problem);
            },
            field.member);
}

/// Sets a field of the table on top of the stack for each field of `table` in `def`,
/// named as in the table (a pointer's is left out).
template <class Def, class F, std::size_t N>
void setFields(lua_State* L, const Def& def, const F (&table)[N]) {
    for (const F& field : table) {
        auto push = [&](auto member) { return pushField(L, def.*member); };
        if (std::visit(push, field.member))
            lua_setfield(L, -2, field.property->name);
    }
}

/// A definition's values held apart from it, one a row of its table, each starting at its
/// property's default: for a definition with a destructor (TileMapDef's rows), which no
/// frame that may raise a Lua error may hold (args.hpp).
template <std::size_t N> using Values = std::array<properties::Value, N>;

template <class F, std::size_t N> Values<N> defaultsOf(const F (&table)[N]) {
    Values<N> values;
    for (std::size_t i = 0; i < N; ++i)
        values[i] = table[i].property->byDefault;
    return values;
}

/// Reads the Lua table's fields into `values`, in table order, then after(field, value of
/// the field, given) for each; pointers are left at their defaults.
template <class F, std::size_t N, class After>
void readValues(const Fields& fields, Values<N>& values, const F (&table)[N], After&& after) {
    for (std::size_t i = 0; i < N; ++i) {
        auto read = [&](auto value) {
            const bool given = readField(fields, *table[i].property, value);
            values[i] = value;
            return given;
        };
        after(table[i], values[i], std::visit(read, values[i]));
    }
}

/// The values of `def`'s fields, and `def`'s fields set to the values.
template <class Def, class F, std::size_t N>
Values<N> valuesOf(const Def& def, const F (&table)[N]) {
    Values<N> values;
    for (std::size_t i = 0; i < N; ++i)
        std::visit([&](auto member) { values[i] = def.*member; }, table[i].member);
    return values;
}
template <class Def, class F, std::size_t N>
void setValues(Def& def, const Values<N>& values, const F (&table)[N]) {
    for (std::size_t i = 0; i < N; ++i)
        std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(def.*member)>;
                def.*member = std::get<T>(values[i]);
            },
            table[i].member);
}

/// Sets a field of the table on top of the stack for each value, named by its row.
template <class F, std::size_t N>
void setValueFields(lua_State* L, const Values<N>& values, const F (&table)[N]) {
    for (std::size_t i = 0; i < N; ++i)
        if (std::visit([&](auto value) { return pushField(L, value); }, values[i]))
            lua_setfield(L, -2, table[i].property->name);
}

} // namespace jostle::lua
