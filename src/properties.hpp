// Settings described once: a Property is a setting's name, its type (its default's), the
// rule its values follow and its default; a Field binds a property to the member of a
// definition that holds it and to the member of the definition's C struct. Tables of
// fields (body_properties.hpp: bodies and tile maps; world_options.hpp: worlds and their
// options) are walked by the checks (checkBodyDef, checkTileMapDef, checkWorldDef), the
// scene loader, the C API's conversions and the Lua module, instead of each listing the
// settings again. This file has what every table shares: the rules, and walking a table.
#pragma once

#include "jostle/body.hpp"
#include "jostle/jostle.h"
#include "jostle/world.hpp"
#include "range_check.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace jostle::properties {

// --- Rules -------------------------------------------------------------------------------

/// What values a property takes: a few checks made in order (stepsOf), each giving the
/// problem in the words errors use ("must be > 0"), or nullptr.
enum class Rule : std::uint8_t {
    Any,                ///< every value of its type: bits, flags, user data, a name jostle has
    Finite,             ///< a number in range (math.hpp), or a vector of two (gravity)
    Size,               ///< in range, > 0 and >= 1e-9: half extents, density
    Unit,               ///< in [0, 1]
    NonNegative,        ///< in range and >= 0
    MassOrZero,         ///< in range, >= 0, and 0 (the mass comes from density) or >= 1e-9
    Direction,          ///< a vector: {0, 0} or a unit vector along x or y (oneWay)
    Corner,             ///< a vector: {0, 0} or each component -1 or +1 (slope)
    FloorAngle,         ///< degrees in [0, 90)
    Interval,           ///< in the property's interval (Property::range): iterations, slop
    PositiveOrInfinity, ///< > 0, infinity (no limit) included: maxVelocity
    FiniteNonNegative,  ///< a finite number >= 0, of any magnitude: restitutionThreshold
};

/// The numbers from `low` to `high`, each end in or out, and the words that say so
/// ("must be in (0, 1]"), written once when the interval is made: the bounds of a rule are
/// written once, where its property is.
struct Interval {
    double low = 0.0;
    double high = 0.0;
    bool lowIn = true;
    bool highIn = true;
    char words[48] = {};

    constexpr Interval() = default;
    constexpr Interval(double l, double h, bool li = true, bool hi = true)
        : low(l), high(h), lowIn(li), highIn(hi) {
        char* out = words;
        for (const char c : std::string_view("must be in "))
            *out++ = c;
        *out++ = lowIn ? '[' : '(';
        out = write(out, low);
        *out++ = ',';
        *out++ = ' ';
        out = write(out, high);
        *out++ = highIn ? ']' : ')';
    }

    constexpr bool contains(double v) const {
        return (lowIn ? v >= low : v > low) && (highIn ? v <= high : v < high);
    }

private:
    /// Writes a bound as %g would: a whole part of at most ten digits, then at most six
    /// decimals (1000, 0.5).
    static constexpr char* write(char* out, double v) {
        if (v < 0.0) {
            *out++ = '-';
            v = -v;
        }
        auto whole = static_cast<std::uint64_t>(v);
        double fraction = v - static_cast<double>(whole);
        char digits[20] = {};
        int count = 0;
        do {
            digits[count++] = static_cast<char>('0' + whole % 10);
            whole /= 10;
        } while (whole > 0);
        while (count > 0)
            *out++ = digits[--count];
        if (fraction > 1e-9)
            *out++ = '.';
        for (int decimals = 0; decimals < 6 && fraction > 1e-9; ++decimals) {
            fraction *= 10.0;
            const int digit = static_cast<int>(fraction);
            *out++ = static_cast<char>('0' + digit);
            fraction -= digit;
        }
        return out;
    }
};

namespace checks {
inline const char* inRange(float v) {
    return rangeProblem(v);
}
inline const char* positive(float v) {
    return v > 0.0f ? nullptr : "must be > 0";
}
inline const char* notTiny(float v) {
    return v >= kMinMagnitude ? nullptr : "must be >= 1e-9";
}
inline const char* unit(float v) {
    return v >= 0.0f && v <= 1.0f ? nullptr : "must be in [0, 1]";
}
inline const char* nonNegative(float v) {
    return v >= 0.0f ? nullptr : "must be >= 0";
}
inline const char* massNonNegative(float v) {
    return v >= 0.0f ? nullptr : "must be >= 0 (0: from density)";
}
inline const char* floorAngle(float v) {
    return v >= 0.0f && v < 90.0f ? nullptr : "must be in [0, 90)";
}
inline const char* massZeroOrNotTiny(float v) {
    return v == 0.0f || v >= kMinMagnitude ? nullptr : "must be 0 (from density) or >= 1e-9";
}
inline const char* finiteNonNegative(float v) {
    return v >= 0.0f && !std::isinf(v) ? nullptr : "must be a finite number >= 0";
}
} // namespace checks

using NumberCheck = const char* (*)(float);
inline constexpr std::size_t kMaxSteps = 3;

/// The checks of a rule on numbers, in order; none for the other rules (and for Interval,
/// whose check is its property's interval).
constexpr std::array<NumberCheck, kMaxSteps> stepsOf(Rule rule) {
    using namespace checks;
    switch (rule) {
    case Rule::Finite:
        return {inRange};
    case Rule::Size:
        return {inRange, positive, notTiny};
    case Rule::Unit:
        return {unit}; // which no NaN passes: a setter's NaN is "not in [0, 1]"
    case Rule::NonNegative:
        return {inRange, nonNegative};
    case Rule::MassOrZero:
        return {inRange, massNonNegative, massZeroOrNotTiny};
    case Rule::FloorAngle:
        return {floorAngle}; // which no NaN passes
    case Rule::PositiveOrInfinity:
        return {positive}; // which no NaN passes, and infinity does
    case Rule::FiniteNonNegative:
        return {finiteNonNegative};
    case Rule::Any:
    case Rule::Direction:
    case Rule::Corner:
    case Rule::Interval:
        break;
    }
    return {};
}

/// Whether a value is one jostle can hold at all, whatever its property: a number in
/// range (each of a vector's on its own), a name jostle has. A body's definition is checked
/// for this first, so that no rule ever sees a NaN.
inline const char* formProblem(float value) {
    return rangeProblem(value);
}
inline const char* formProblem(Vec2 value) {
    const char* problem = rangeProblem(value.x);
    return problem ? problem : rangeProblem(value.y);
}
inline const char* formProblem(BodyType type) {
    const bool named =
        type == BodyType::Static || type == BodyType::Kinematic || type == BodyType::Dynamic;
    return named ? nullptr : "must be static, kinematic or dynamic";
}
inline const char* formProblem(Solver solver) {
    const bool named = solver == Solver::Classic || solver == Solver::Physical;
    return named ? nullptr : "must be classic or physical";
}
inline const char* formProblem(FrictionMix mix) {
    const bool named = mix == FrictionMix::Min || mix == FrictionMix::GeometricMean;
    return named ? nullptr : "must be min or geometricMean";
}
template <class T> const char* formProblem(T) {
    return nullptr;
}

/// Check number `step` of `rule` on one value: its problem, or nullptr if it passes or the
/// rule has no such check. Rule::Any asks for the value's form: a name jostle has.
inline const char* stepProblem(Rule rule, std::size_t step, float value) {
    const NumberCheck check = stepsOf(rule)[step];
    return check ? check(value) : nullptr;
}
inline const char* stepProblem(Rule rule, std::size_t step, Vec2 value) {
    if (step != 0)
        return nullptr;
    if (rule == Rule::Direction && !isValidOneWay(value))
        return "must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}";
    if (rule == Rule::Corner && !isValidSlope(value))
        return "must be {0, 0} or each component -1 or 1";
    if (rule == Rule::Finite)
        return rangeProblem(value); // both numbers at once: "must be finite numbers"
    return nullptr;
}
template <class T> const char* stepProblem(Rule, std::size_t step, T value) {
    return step == 0 ? formProblem(value) : nullptr; // Rule::Any, Rule::Interval's form
}

/// The problem with one value under `rule`, all its checks in order (a setter's argument).
template <class T> const char* problemOf(Rule rule, T value) {
    for (std::size_t step = 0; step < kMaxSteps; ++step)
        if (const char* problem = stepProblem(rule, step, value))
            return problem;
    return nullptr;
}

// --- Properties --------------------------------------------------------------------------

/// A value of any property's type.
using Value =
    std::variant<BodyType, float, Vec2, bool, std::uint32_t, void*, int, Solver, FrictionMix>;

/// One property, as every definition that has it describes it.
struct Property {
    const char* name; ///< the member's name, which is also the scene file's and Lua's field
    Rule rule;
    Value byDefault;
    /// Scene files and Lua tables must give it: no default makes sense (a box's size).
    bool required = false;
    /// Rule::Interval's numbers.
    Interval range{};
};

/// A property whose values lie in `range` (Rule::Interval).
constexpr Property inInterval(const char* name, Value byDefault, Interval range) {
    return {name, Rule::Interval, byDefault, false, range};
}

/// Check number `step` of the property's rule on one value (stepProblem), its interval's
/// included.
template <class T> const char* stepProblem(const Property& p, std::size_t step, T value) {
    if constexpr (std::is_arithmetic_v<T>)
        if (p.rule == Rule::Interval && step == 0 && !p.range.contains(static_cast<double>(value)))
            return p.range.words;
    return stepProblem(p.rule, step, value);
}

/// The problem with one value of the property, all its checks in order.
template <class T> const char* problemOf(const Property& p, T value) {
    for (std::size_t step = 0; step < kMaxSteps; ++step)
        if (const char* problem = stepProblem(p, step, value))
            return problem;
    return nullptr;
}

/// The C API's type for a property's type.
template <class T> struct CTypeOf { using type = T; };
template <> struct CTypeOf<BodyType> { using type = jostle_body_type; };
template <> struct CTypeOf<Vec2> { using type = jostle_vec2; };
template <> struct CTypeOf<Solver> { using type = jostle_solver; };
template <> struct CTypeOf<FrictionMix> { using type = jostle_friction_mix; };
template <class T> using CType = typename CTypeOf<T>::type;

/// True if `rule` is one for values of type T.
template <class T> constexpr bool ruleFits(Rule rule) {
    if constexpr (std::is_same_v<T, float>)
        return rule != Rule::Direction && rule != Rule::Corner;
    else if constexpr (std::is_same_v<T, Vec2>)
        return rule == Rule::Direction || rule == Rule::Corner || rule == Rule::Finite ||
               rule == Rule::Any;
    else if constexpr (std::is_same_v<T, int>)
        return rule == Rule::Interval || rule == Rule::Any;
    else
        return rule == Rule::Any;
}

/// A property as a member of the definition Def and of its C struct CDef (whose member is
/// the property's C name: gravity_scale, one_way, user_data). T... are the types of the
/// definition's properties.
template <class Def, class CDef, class... T> struct Field {
    template <class U>
    constexpr Field(const Property& p, U Def::*m, CType<U> CDef::*c)
        : property(&p), member(m), cMember(c) {
        // In a constexpr table, a property bound to a member of another type does not compile.
        if (!std::holds_alternative<U>(p.byDefault) || !ruleFits<U>(p.rule))
            throw "a property's type, rule and member disagree";
    }

    /// Calls f(member, cMember) with both member pointers of their own types.
    template <class F> void visitWithC(F&& f) const {
        std::visit(
            [&](auto m) {
                using U = std::remove_cvref_t<decltype(std::declval<Def&>().*m)>;
                f(m, std::get<CType<U> CDef::*>(cMember));
            },
            member);
    }

    const Property* property;
    std::variant<T Def::*...> member;
    std::variant<CType<T> CDef::*...> cMember;
};

// --- Walking a table ---------------------------------------------------------------------

/// The field named `name`, or nullptr.
template <class F, std::size_t N>
constexpr const F* find(const F (&fields)[N], std::string_view name) {
    for (const F& field : fields)
        if (name == field.property->name)
            return &field;
    return nullptr;
}

/// The field of `property`, or nullptr.
template <class F, std::size_t N>
constexpr const F* find(const F (&fields)[N], const Property& property) {
    for (const F& field : fields)
        if (field.property == &property)
            return &field;
    return nullptr;
}

/// The first value of `def` not of a form jostle can hold (formProblem), in table order.
template <class Def, class F, std::size_t N>
std::optional<FieldError> formProblem(const Def& def, const F (&fields)[N]) {
    for (const F& field : fields) {
        auto check = [&](auto member) { return formProblem(def.*member); };
        if (const char* problem = std::visit(check, field.member))
            return FieldError{field.property->name, problem};
    }
    return std::nullopt;
}

/// The first value of `def` that its rule refuses, in table order. Fields side by side
/// under one rule (hw, hh) take each check in turn: both > 0 before either's minimum.
template <class Def, class F, std::size_t N>
std::optional<FieldError> ruleProblem(const Def& def, const F (&fields)[N]) {
    for (std::size_t begin = 0, end = 0; begin < N; begin = end) {
        const Rule rule = fields[begin].property->rule;
        for (end = begin + 1; end < N && fields[end].property->rule == rule; ++end) {
        }
        for (std::size_t step = 0; step < kMaxSteps; ++step)
            for (std::size_t i = begin; i < end; ++i) {
                const Property& property = *fields[i].property;
                auto check = [&](auto member) { return stepProblem(property, step, def.*member); };
                if (const char* problem = std::visit(check, fields[i].member))
                    return FieldError{property.name, problem};
            }
    }
    return std::nullopt;
}

/// True if value `I` of `def` by table `Fields` has a form jostle holds and passes its rule.
/// The table is a constant, so each row's member and rule are known where this is compiled.
template <const auto& Fields, std::size_t I, class Def> bool passes(const Def& def) {
    constexpr auto member = std::get<Fields[I].member.index()>(Fields[I].member);
    constexpr const Property& property = *Fields[I].property;
    const auto value = def.*member;
    if (formProblem(value) != nullptr)
        return false;
    if constexpr (std::is_same_v<decltype(value), const float> && property.rule != Rule::Interval) {
        constexpr std::array<NumberCheck, kMaxSteps> steps = stepsOf(property.rule);
        for (NumberCheck check : steps) // known here: each call is inlined
            if (check != nullptr && check(value) != nullptr)
                return false;
        return true;
    } else {
        return problemOf(property, value) == nullptr;
    }
}

/// True if formProblem and ruleProblem find nothing in `def`: the quick test of a
/// definition, row after row with no look-ups, before the walks that say what fails first.
template <const auto& Fields, class Def> bool allPass(const Def& def) {
    return [&]<std::size_t... I>(std::index_sequence<I...>) {
        return (passes<Fields, I>(def) && ...);
    }(std::make_index_sequence<std::size(Fields)>{});
}

/// True if every field of `defaults` (a default-made Def) holds its property's default.
template <class Def, class F, std::size_t N>
constexpr bool defaultsAgree(const Def& defaults, const F (&fields)[N]) {
    for (const F& field : fields) {
        auto agrees = [&](auto member) {
            using T = std::remove_cvref_t<decltype(defaults.*member)>;
            return defaults.*member == std::get<T>(field.property->byDefault);
        };
        if (!std::visit(agrees, field.member))
            return false;
    }
    return true;
}

} // namespace jostle::properties
