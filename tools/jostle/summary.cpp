// The human summary: what was run, how long it took, where the moving bodies ended.
#include "summary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace jostle::cli {

namespace {

// A summary is read, not parsed: a screenful of bodies says enough, and the trace has
// them all.
constexpr std::size_t kMaxRows = 20;
/// The summary's numbers: this many significant digits at the scene's size, at most this
/// many decimals. The trace prints every float exactly (trace.cpp).
constexpr int kSignificantDigits = 5;
constexpr int kMaxDecimals = 9;

/// How far the scene reaches from the origin: the largest |coordinate| of its bodies'
/// boxes and its tile maps, as the file gives them. Float noise in a position is about
/// 1e-7 of this; a value left over from float arithmetic on velocities is far smaller.
double sceneSize(const Scene& scene) {
    double size = 0.0;
    // The span from `at` to `at + length` along one axis.
    const auto reach = [&size](float at, float length, std::size_t count = 1) {
        const double from = static_cast<double>(at);
        const double to = from + static_cast<double>(length) * static_cast<double>(count);
        size = std::max({size, std::abs(from), std::abs(to)});
    };
    for (const SceneBody& body : scene.bodies) {
        reach(body.def.x - body.def.hw, 2.0f * body.def.hw);
        reach(body.def.y - body.def.hh, 2.0f * body.def.hh);
    }
    for (const TileMapDef& map : scene.tileMaps) {
        reach(map.x, map.tile, map.rows.empty() ? 0 : map.rows.front().size());
        reach(map.y, map.tile, map.rows.size());
    }
    return size;
}

/// Decimals that give five significant digits at the scene's size: 2 for a level 800 px
/// wide, 4 for one of 5 m. Positions and velocities alike are printed to them, so what is
/// float noise next to the scene's scale (1e-19, -1.4e-45) reads as 0.
int decimalsFor(double size) {
    if (!(size > 0.0) || !std::isfinite(size))
        return 4;
    return std::clamp(kSignificantDigits - 1 - static_cast<int>(std::floor(std::log10(size))), 0,
                      kMaxDecimals);
}

/// `value` to `decimals` places, without trailing zeros, and never "-0".
std::string number(float value, int decimals) {
    char text[64]; // the largest float has 39 digits
    std::snprintf(text, sizeof text, "%.*f", decimals, static_cast<double>(value));
    std::string result = text;
    if (result.find('.') != std::string::npos) {
        result.erase(result.find_last_not_of('0') + 1);
        if (result.back() == '.')
            result.pop_back();
    }
    if (result == "-0")
        result = "0";
    return result;
}

std::string onOff(bool on) {
    return on ? "on" : "off";
}

} // namespace

void printSummary(std::FILE* out, const RunReport& report) {
    const Scene& scene = report.scene;
    std::array<std::size_t, 3> byType{};
    for (const SceneBody& body : scene.bodies)
        ++byType[static_cast<std::size_t>(body.def.type)];

    std::string solver = toString(scene.world.solver);
    if (scene.world.solver == Solver::Classic)
        solver += " (mass " + onOff(scene.world.classic.mass) + ", coulomb " +
                  onOff(scene.world.classic.coulomb) + ")";

    const double dt = static_cast<double>(scene.dt);
    const double seconds = dt * static_cast<double>(report.steps);
    const double wallMs = std::chrono::duration<double, std::milli>(report.wallTime).count();

    std::fprintf(out, "scene      %s\n", report.scenePath.c_str());
    std::fprintf(out, "solver     %s\n", solver.c_str());
    std::fprintf(out, "bodies     %zu (%zu static, %zu kinematic, %zu dynamic)\n",
                 scene.bodies.size(), byType[static_cast<std::size_t>(BodyType::Static)],
                 byType[static_cast<std::size_t>(BodyType::Kinematic)],
                 byType[static_cast<std::size_t>(BodyType::Dynamic)]);
    std::fprintf(out, "steps      %lld of %.6g s = %.6g s simulated\n",
                 static_cast<long long>(report.steps), dt, seconds);
    std::fprintf(out, "wall time  %.3f ms\n", wallMs);

    // The final state of the moving bodies, as a table with columns as wide as needed.
    std::vector<std::array<std::string, 5>> rows;
    rows.push_back({"id", "x", "y", "vx", "vy"});
    std::size_t moving = 0;
    const int decimals = decimalsFor(sceneSize(scene));
    const auto cell = [decimals](float value) { return number(value, decimals); };
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (scene.bodies[i].def.type == BodyType::Static)
            continue;
        if (++moving > kMaxRows)
            continue;
        const Vec2 p = report.world.position(report.bodies[i]);
        const Vec2 v = report.world.velocity(report.bodies[i]);
        rows.push_back({scene.bodies[i].id, cell(p.x), cell(p.y), cell(v.x), cell(v.y)});
    }
    if (moving == 0)
        return;

    std::array<std::size_t, 5> widths{};
    for (const auto& row : rows)
        for (std::size_t c = 0; c < row.size(); ++c)
            widths[c] = std::max(widths[c], row[c].size());
    std::fputc('\n', out);
    for (const auto& row : rows) {
        // The id left-aligned, the numbers right-aligned so their digits line up.
        std::fprintf(out, "%-*s", static_cast<int>(widths[0]), row[0].c_str());
        for (std::size_t c = 1; c < row.size(); ++c)
            std::fprintf(out, "  %*s", static_cast<int>(widths[c]), row[c].c_str());
        std::fputc('\n', out);
    }
    if (moving > kMaxRows)
        std::fprintf(out, "... and %zu more (use --trace for all)\n", moving - kMaxRows);
}

} // namespace jostle::cli
