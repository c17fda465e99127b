// bench/report.hpp: the results as a table for people (plain or markdown) and as CSV.
#pragma once

#include "runner.hpp"

#include <cstdio>
#include <optional>
#include <span>
#include <string>

namespace jostle::bench {

/// jostle's time (sleeping off) over this result's, for a peer of the same case:
/// below 1, jostle is faster. Empty for jostle's own rows or when jostle did not run.
std::optional<double> jostleRatio(std::span<const RunResult> all, const RunResult& result);

/// For a result on several workers: the same engine's time on one worker over this one's.
std::optional<double> speedUp(std::span<const RunResult> all, const RunResult& result);

/// The table, one row per result, in the order given. Markdown: a GitHub table.
void printTable(std::FILE* out, std::span<const RunResult> results, bool markdown);

/// For the results that profiled their steps (jostle's), the mean milliseconds of each
/// stage of the step (World::profile), a row per result. Markdown: a GitHub table.
void printStages(std::FILE* out, std::span<const RunResult> results, bool markdown);

/// For the results that measured snapshots (jostle's, --snapshots): the bytes and the
/// medians of save, restore and state hash, beside a step. Markdown: a GitHub table.
void printSnapshots(std::FILE* out, std::span<const RunResult> results, bool markdown);

/// Writes the results as CSV with a header row; false if the file cannot be written.
bool writeCsv(const std::string& path, std::span<const RunResult> results);

} // namespace jostle::bench
