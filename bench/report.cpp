// Tables and CSV.
#include "report.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace jostle::bench {
namespace {

std::string format(const char* pattern, double value) {
    std::array<char, 64> text{};
    std::snprintf(text.data(), text.size(), pattern, value);
    return text.data();
}

/// Three significant figures at most, without exponent for the usual range.
std::string milliseconds(double ms) {
    if (ms >= 100.0)
        return format("%.0f", ms);
    if (ms >= 10.0)
        return format("%.1f", ms);
    if (ms >= 1.0)
        return format("%.2f", ms);
    return format("%.3f", ms);
}

std::string length(float value) {
    if (!std::isfinite(value))
        return "lost";
    return format("%.3f", static_cast<double>(value));
}

using Cells = std::vector<std::string>;

const Cells kHeader{"scene",       "bodies",     "engine",  "steps",     "ms/step",     "speed-up",
                    "jostle/peer", "bytes/body", "peak MB", "top drift", "max overlap", "escaped"};

Cells makeRow(std::span<const RunResult> all, const RunResult& r) {
    const std::optional<double> ratio = jostleRatio(all, r);
    const std::optional<double> faster = speedUp(all, r);
    return {
        r.caseName,
        std::to_string(r.bodies),
        label(r),
        std::to_string(r.warmupSteps) + "+" + std::to_string(r.measuredSteps),
        milliseconds(r.msPerStep),
        faster ? format("%.2f", *faster) : "-",
        ratio ? format("%.2f", *ratio) : "-",
        format("%.0f", r.bytesPerBody),
        format("%.1f", r.peakBytes / 1e6),
        r.quality.topDrift ? length(*r.quality.topDrift) : "-",
        length(r.quality.maxPenetration),
        std::to_string(r.quality.escaped),
    };
}

/// Rows under a header, each column as wide as its widest cell: the scene (column 0) and
/// the engine (column 2) to the left, numbers to the right. Plain text puts a blank line
/// between scenes; markdown makes a GitHub table.
void printGrid(std::FILE* out, const Cells& header, const std::vector<Cells>& rows, bool markdown) {
    std::vector<std::size_t> width(header.size());
    for (std::size_t c = 0; c < header.size(); ++c) {
        width[c] = header[c].size();
        for (const Cells& row : rows)
            width[c] = std::max(width[c], row[c].size());
    }
    const auto leftAligned = [](std::size_t c) { return c == 0 || c == 2; };
    const auto printRow = [&](const Cells& cells) {
        for (std::size_t c = 0; c < header.size(); ++c) {
            const int w = static_cast<int>(width[c]);
            if (markdown)
                std::fprintf(out, "| %*s ", leftAligned(c) ? -w : w, cells[c].c_str());
            else
                std::fprintf(out, c == 0 ? "%*s" : "  %*s", leftAligned(c) ? -w : w,
                             cells[c].c_str());
        }
        std::fputs(markdown ? "|\n" : "\n", out);
    };

    printRow(header);
    if (markdown) {
        for (std::size_t c = 0; c < header.size(); ++c) {
            std::string rule(width[c] + 2, '-');
            if (!leftAligned(c))
                rule.back() = ':';
            std::fprintf(out, "|%s", rule.c_str());
        }
        std::fputs("|\n", out);
    }
    std::string previous;
    for (const Cells& row : rows) {
        if (!markdown && !previous.empty() && row[0] != previous)
            std::fputc('\n', out);
        previous = row[0];
        printRow(row);
    }
}

} // namespace

std::optional<double> jostleRatio(std::span<const RunResult> all, const RunResult& result) {
    if (result.engine != EngineKind::Box2D && result.engine != EngineKind::Chipmunk &&
        result.engine != EngineKind::Box2D3)
        return std::nullopt;
    // A peer on N workers (Box2D v3) against jostle on as many.
    for (const RunResult& other : all)
        if (other.caseName == result.caseName && other.engine == EngineKind::Jostle &&
            other.workers == result.workers && result.msPerStep > 0.0)
            return other.msPerStep / result.msPerStep;
    return std::nullopt;
}

std::optional<double> speedUp(std::span<const RunResult> all, const RunResult& result) {
    if (result.workers == 1)
        return std::nullopt;
    for (const RunResult& other : all)
        if (other.caseName == result.caseName && other.engine == result.engine &&
            other.workers == 1 && result.msPerStep > 0.0)
            return other.msPerStep / result.msPerStep;
    return std::nullopt;
}

void printTable(std::FILE* out, std::span<const RunResult> results, bool markdown) {
    std::vector<Cells> rows;
    for (const RunResult& r : results)
        rows.push_back(makeRow(results, r));
    printGrid(out, kHeader, rows, markdown);
}

void printStages(std::FILE* out, std::span<const RunResult> results, bool markdown) {
    Cells header{"scene", "bodies", "engine"};
    for (const StageField& stage : kStages)
        header.emplace_back(stage.name);
    std::vector<Cells> rows;
    for (const RunResult& r : results) {
        if (!r.stages)
            continue;
        Cells row{r.caseName, std::to_string(r.bodies), label(r)};
        for (const StageField& stage : kStages)
            row.push_back(milliseconds(static_cast<double>(*r.stages.*stage.ms)));
        rows.push_back(std::move(row));
    }
    printGrid(out, header, rows, markdown);
}

void printSnapshots(std::FILE* out, std::span<const RunResult> results, bool markdown) {
    const Cells header{"scene",   "bodies",     "engine",  "bytes",   "bytes/body",
                       "save µs", "restore µs", "hash µs", "step µs", "save/step"};
    std::vector<Cells> rows;
    auto number = [](double value, int decimals) {
        char text[32];
        std::snprintf(text, sizeof text, "%.*f", decimals, value);
        return std::string(text);
    };
    for (const RunResult& r : results) {
        if (!r.snapshots)
            continue;
        const SnapshotFigures& s = *r.snapshots;
        const double stepMicroseconds = r.msPerStep * 1000.0;
        rows.push_back({r.caseName, std::to_string(r.bodies), label(r), std::to_string(s.bytes),
                        number(double(s.bytes) / double(std::max(r.bodies, 1)), 0),
                        number(s.saveMicroseconds, 0), number(s.restoreMicroseconds, 0),
                        number(s.hashMicroseconds, 0), number(stepMicroseconds, 0),
                        number(s.saveMicroseconds / std::max(stepMicroseconds, 1e-9), 2)});
    }
    printGrid(out, header, rows, markdown);
}

bool writeCsv(const std::string& path, std::span<const RunResult> results) {
    struct Closer {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    std::unique_ptr<std::FILE, Closer> file(std::fopen(path.c_str(), "w"));
    if (!file)
        return false;
    std::FILE* out = file.get();
    std::fputs("scene,family,size,engine,workers,bodies,warmup_steps,measured_steps,ms_per_step,"
               "speed_up,jostle_over_engine,bytes_per_body,top_drift,max_overlap,escaped,peak_mb\n",
               out);
    for (const RunResult& r : results) {
        const std::optional<double> ratio = jostleRatio(results, r);
        const std::optional<double> faster = speedUp(results, r);
        std::fprintf(out, "%s,%s,%d,%.*s,%d,%d,%d,%d,%.6f,", r.caseName.c_str(), r.family.c_str(),
                     r.size, static_cast<int>(name(r.engine).size()), name(r.engine).data(),
                     r.workers, r.bodies, r.warmupSteps, r.measuredSteps, r.msPerStep);
        if (faster)
            std::fprintf(out, "%.6f", *faster);
        std::fputc(',', out);
        if (ratio)
            std::fprintf(out, "%.6f", *ratio);
        std::fprintf(out, ",%.1f,", r.bytesPerBody);
        if (r.quality.topDrift)
            std::fprintf(out, "%.6g", static_cast<double>(*r.quality.topDrift));
        std::fprintf(out, ",%.6g,%d,%.3f\n", static_cast<double>(r.quality.maxPenetration),
                     r.quality.escaped, r.peakBytes / 1e6);
    }
    const bool ok = std::fflush(out) == 0 && !std::ferror(out);
    return std::fclose(file.release()) == 0 && ok;
}

} // namespace jostle::bench
