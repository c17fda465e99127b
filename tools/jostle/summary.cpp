// The human summary: what was run, how long it took, where the moving bodies ended.
#include "summary.hpp"

#include <algorithm>
#include <array>
#include <vector>

namespace jostle::cli {

namespace {

// A summary is read, not parsed: a screenful of bodies says enough, and the trace has
// them all.
constexpr std::size_t kMaxRows = 20;

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", static_cast<double>(value));
    return text;
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
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        if (scene.bodies[i].def.type == BodyType::Static)
            continue;
        if (++moving > kMaxRows)
            continue;
        const Vec2 p = report.world.position(report.bodies[i]);
        const Vec2 v = report.world.velocity(report.bodies[i]);
        rows.push_back({scene.bodies[i].id, number(p.x), number(p.y), number(v.x), number(v.y)});
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
