// jostle-bench-load: loading big scene files, timed, with the memory it takes.
//
//     jostle-bench-load                    a million bodies (docs/benchmarks.md)
//     jostle-bench-load --bodies 200000    another size
//
// Writes three scene files of about the same size into a temporary folder and loads each
// with jostle::loadScene: one whose bodies all load; one whose first field is unknown and
// holds the same bodies, refused at its name; and one whose "gravity" holds them, read to
// its end and refused for its type. For each: the file's size, the time to load (the
// median of --runs), the heap the loaded scene holds, and the peak resident memory of the
// process so far. The refused files are loaded first, so that their peaks are their own.
// Exit status: 0 when both did what they should; 2 for bad options; 1 otherwise.
#include "memory.hpp"

#include "jostle/scene.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace {

constexpr int kBadInput = 2;
constexpr int kFailure = 1;

/// Where a file's bodies are: in "bodies", in an unknown field, in a field of another type.
enum class Holder { Bodies, Unknown, WrongType };

/// Writes a scene of `bodies` boxes in rows of 1000, each line a body as a level editor
/// would write it, as the value of `holder`'s field (before an empty "bodies" if that is
/// not it). Returns the file's size.
std::uintmax_t writeScene(const std::filesystem::path& path, long bodies, Holder holder) {
    std::ofstream out(path, std::ios::binary);
    out << (holder == Holder::Bodies    ? "{\"gravity\": [0, 10], \"bodies\": [\n"
            : holder == Holder::Unknown ? "{\"props\": [\n"
                                        : "{\"gravity\": [\n");
    for (long i = 0; i < bodies; ++i)
        out << "{\"id\": \"box" << i << "\", \"x\": " << i % 1000 << ", \"y\": " << i / 1000
            << ", \"hw\": 0.5, \"hh\": 0.5, \"friction\": 0.5}" << (i + 1 < bodies ? ",\n" : "\n");
    out << (holder == Holder::Bodies ? "]}\n" : "], \"bodies\": []}\n");
    out.close();
    return std::filesystem::file_size(path);
}

/// The peak resident memory of the process so far, in bytes.
std::size_t peakResident() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<std::size_t>(usage.ru_maxrss) * 1024; // Linux: kilobytes
}

double mebibytes(std::size_t bytes) {
    return static_cast<double>(bytes) / (1024.0 * 1024.0);
}

struct Load {
    double seconds = 0;
    std::size_t bodies = 0;
    std::size_t heldBytes = 0; ///< heap the scene holds
    std::string error;         ///< the SceneError, if refused
};

Load loadOnce(const std::string& path) {
    Load load;
    const std::size_t heapBefore = jostle::bench::heapInUse();
    const auto start = std::chrono::steady_clock::now();
    try {
        const jostle::Scene scene = jostle::loadScene(path);
        load.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        load.bodies = scene.bodies.size();
        load.heldBytes = jostle::bench::heapInUse() - heapBefore;
    } catch (const jostle::SceneError& error) {
        load.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        load.error = error.what();
    }
    return load;
}

/// Loads `path` `runs` times and prints a line; false if the outcome is not the expected one.
bool measure(const char* name, const std::string& path, std::uintmax_t size, int runs,
             bool shouldLoad) {
    std::vector<double> seconds;
    Load load;
    for (int run = 0; run < runs; ++run) {
        load = loadOnce(path);
        seconds.push_back(load.seconds);
    }
    std::sort(seconds.begin(), seconds.end());
    const double median = seconds[seconds.size() / 2];
    std::printf("%-8s %8.1f MiB  %8.3f s  %9zu bodies  %8.1f MiB held  %8.1f MiB peak\n", name,
                mebibytes(size), median, load.bodies, mebibytes(load.heldBytes),
                mebibytes(peakResident()));
    if (!load.error.empty())
        std::printf("         refused: %s\n", load.error.c_str());
    return shouldLoad == load.error.empty();
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"jostle-bench-load: big scene files loaded by jostle::loadScene, timed, with "
                 "their memory (docs/benchmarks.md)"};
    long bodies = 1'000'000;
    int runs = 3;
    app.add_option("--bodies", bodies, "Bodies in each file (default 1000000)")
        ->check(CLI::Range(1L, 20'000'000L));
    app.add_option("--runs", runs, "Loads of each file; the median time is shown (default 3)")
        ->check(CLI::Range(1, 100));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int status = app.exit(error);
        return status == 0 ? 0 : kBadInput;
    }

    const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                      ("jostle-bench-load-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const std::filesystem::path unknown = dir / "unknown.json";
    const std::filesystem::path wrongType = dir / "wrong_type.json";
    const std::filesystem::path scene = dir / "bodies.json";
    const std::uintmax_t unknownSize = writeScene(unknown, bodies, Holder::Unknown);
    const std::uintmax_t wrongTypeSize = writeScene(wrongType, bodies, Holder::WrongType);
    const std::uintmax_t sceneSize = writeScene(scene, bodies, Holder::Bodies);

    std::printf("file         size      load   loaded            scene holds   process peak\n");
    bool ok = measure("unknown", unknown.string(), unknownSize, runs, false);
    ok = measure("type", wrongType.string(), wrongTypeSize, runs, false) && ok;
    ok = measure("bodies", scene.string(), sceneSize, runs, true) && ok;
    std::filesystem::remove_all(dir);
    if (!ok) {
        std::fprintf(stderr, "jostle-bench-load: error: a file did not load or was not refused "
                             "as it should\n");
        return kFailure;
    }
    return 0;
}
