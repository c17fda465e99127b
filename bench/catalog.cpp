// The benchmark's scenes and step counts.
//
// Step counts are chosen so that the default run takes a few minutes on a 2-core machine
// while each figure means something: pyramids stand for several seconds before the top's
// drift is read; rain is measured once the boxes have landed and settled; gas and
// tilemap are busy from the first step and need little warm-up.
#include "catalog.hpp"

#include "shared/scenes.hpp"

#include <algorithm>
#include <charconv>
#include <stdexcept>
#include <system_error>

namespace jostle::bench {
namespace {

constexpr int kManyPyramidRows = 10;

Case makeCase(std::string_view family, int size, int warmup, int steps) {
    Case c;
    c.family = std::string(family);
    c.size = size;
    c.name = c.family + "_" + sizeLabel(size);
    c.warmup = warmup;
    c.steps = steps;
    if (family == "pyramid")
        c.make = [size] { return shared::pyramid(size); };
    else if (family == "many_pyramids")
        c.make = [size] { return shared::manyPyramids(size, kManyPyramidRows); };
    else if (family == "rain")
        c.make = [size] { return shared::rain(size); };
    else if (family == "gas")
        c.make = [size] { return shared::gas(size); };
    else if (family == "tilemap")
        c.make = [size] { return shared::tilemap(size); };
    else if (family == "pile")
        c.make = [size] { return shared::pile(size); };
    else if (family == "long_floor")
        c.make = [size] { return shared::crowdOnFloor(size, 1); };
    else if (family == "tiled_floor")
        c.make = [size] { return shared::crowdOnFloor(size, std::max(1, size / 32)); };
    else if (family == "static_level")
        c.make = [size] { return shared::staticLevel(size); };
    else
        throw std::invalid_argument("unknown scene \"" + std::string(family) + "\"");
    return c;
}

} // namespace

const std::vector<std::string_view>& families() {
    static const std::vector<std::string_view> names{"pyramid", "many_pyramids", "rain", "gas",
                                                     "tilemap"};
    return names;
}

std::string sizeLabel(int size) {
    if (size >= 1000 && size % 1000 == 0)
        return std::to_string(size / 1000) + "k";
    return std::to_string(size);
}

std::vector<Case> defaultCases(bool quick) {
    if (quick)
        return {
            makeCase("pyramid", 10, 10, 20),  makeCase("many_pyramids", 5, 10, 20),
            makeCase("rain", 1000, 60, 20),   makeCase("gas", 1000, 10, 20),
            makeCase("tilemap", 200, 10, 20),
        };
    return {
        makeCase("pyramid", 20, 120, 300),
        makeCase("pyramid", 100, 120, 300),
        // 200 pyramids of 10 rows: 11,000 boxes.
        makeCase("many_pyramids", 200, 120, 240),
        // The boxes have landed by 2 s at 10k and by 3 s at 100k: measured from 4 s on,
        // the settled pile.
        makeCase("rain", 10000, 240, 120),
        makeCase("rain", 100000, 240, 60),
        makeCase("gas", 100000, 30, 60),
        makeCase("tilemap", 10000, 60, 240),
    };
}

/// Scenes run only when named: stress, not speed.
std::vector<Case> stressCases() {
    // 10,000 and 50,000 boxes dropped at one spot: what a step costs, and holds, whatever the
    // scene holds. 10,000
    // boxes resting on one long floor and on 312 floor pieces: a floor that touches
    // thousands of bodies costs what its pieces cost. 10,000 static boxes and 16 that
    // move: what the static ones cost a step.
    return {makeCase("pile", 10000, 0, 10), makeCase("pile", 50000, 0, 3),
            makeCase("long_floor", 10000, 60, 240), makeCase("tiled_floor", 10000, 60, 240),
            makeCase("static_level", 10000, 60, 600)};
}

std::vector<Case> selectCases(std::string_view name, bool quick) {
    std::vector<Case> known = defaultCases(quick);
    for (Case& c : stressCases())
        known.push_back(std::move(c));
    std::vector<Case> chosen;
    for (const Case& c : known)
        if (c.name == name || c.family == name)
            chosen.push_back(c);
    if (!chosen.empty())
        return chosen;

    // family_SIZE, SIZE a whole number, optionally followed by k (thousands).
    const std::size_t split = name.rfind('_');
    if (split != std::string_view::npos) {
        const std::string_view family = name.substr(0, split);
        std::string_view digits = name.substr(split + 1);
        int scale = 1;
        if (!digits.empty() && digits.back() == 'k') {
            scale = 1000;
            digits.remove_suffix(1);
        }
        int size = 0;
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), size);
        const bool whole = !digits.empty() && error == std::errc() &&
                           end == digits.data() + digits.size() && size > 0 &&
                           size <= 10'000'000 / scale;
        for (const Case& c : known)
            if (whole && c.family == family)
                return {makeCase(family, size * scale, c.warmup, c.steps)};
    }
    throw std::invalid_argument("unknown scene \"" + std::string(name) + "\"");
}

std::vector<Case> seriesCases(std::string_view family, bool quick) {
    std::vector<int> sizes;
    int warmup = 30;
    int steps = 60;
    if (family == "pyramid") {
        sizes = quick ? std::vector<int>{5, 10} : std::vector<int>{10, 20, 40, 70, 100, 140};
        warmup = 60;
        steps = 120;
    } else if (family == "many_pyramids") {
        sizes = quick ? std::vector<int>{2, 4} : std::vector<int>{10, 30, 100, 300, 1000};
        warmup = 60;
        steps = 120;
    } else if (family == "rain") {
        sizes = quick ? std::vector<int>{300, 1000}
                      : std::vector<int>{1000, 3000, 10000, 30000, 100000};
        warmup = 240;
        steps = 60;
    } else if (family == "gas") {
        sizes = quick ? std::vector<int>{300, 1000}
                      : std::vector<int>{1000, 3000, 10000, 30000, 100000};
    } else if (family == "tilemap") {
        // 100,000 actors make 190,000 bodies, whose warm-up takes the peers many minutes.
        sizes = quick ? std::vector<int>{300, 1000} : std::vector<int>{1000, 3000, 10000, 30000};
    } else {
        throw std::invalid_argument("unknown scene \"" + std::string(family) + "\"");
    }
    if (quick) {
        warmup = 10;
        steps = 20;
    }
    std::vector<Case> cases;
    for (const int size : sizes)
        cases.push_back(makeCase(family, size, warmup, steps));
    return cases;
}

} // namespace jostle::bench
