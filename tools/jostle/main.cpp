// The `jostle` program: runs scene files from the command line (docs/scene-format.md).
//
//     jostle run SCENE --steps N [--trace FILE|-] [--every K] [--solver MODEL]
//     jostle render SCENE --out FILE.gif|FILE.png [--steps N] [--width W] [--height H]
//                   [--every K] [--solver MODEL] [--legend] [--debug]
//     jostle synctest SCENE [--steps N] [--rollback K] [--workers W] [--solver MODEL]
//
// Exit status: 0 when all went well; 2 for bad input (options, scene file, a value the
// world refuses); 1 when the output cannot be written, synctest finds a difference, or
// something unexpected fails.
// Progress of the steps on standard error when it is a terminal (progress.hpp).
#include "errors.hpp"
#include "load_scene.hpp"
#include "progress.hpp"
#include "render.hpp"
#include "summary.hpp"
#include "synctest.hpp"
#include "trace.hpp"

#include "jostle/scene.hpp"
#include "jostle/version.h"

#include <CLI/CLI.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using jostle::cli::kBadInput;
using jostle::cli::kFailure;
using jostle::cli::printError;
using jostle::cli::printWarning;
using jostle::cli::systemMessage;

struct RunOptions {
    std::string scene;
    std::int64_t steps = 0;
    std::string trace; ///< empty: no trace; "-": stdout
    std::int64_t every = 1;
    std::string solver; ///< --solver: "classic" or "physical"; empty: the scene's own
};

/// Accepts whole numbers from minimum to maximum, and says so in a sentence when it
/// refuses.
CLI::Validator inRange(std::int64_t minimum, std::int64_t maximum) {
    const std::string rule = maximum == std::numeric_limits<std::int64_t>::max()
                                 ? ">= " + std::to_string(minimum)
                                 : std::to_string(minimum) + " to " + std::to_string(maximum);
    return CLI::Validator(
        [minimum, maximum, rule](std::string& text) -> std::string {
            std::int64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (error != std::errc() || stop != end)
                return "expected a whole number " + rule + ", got " + text;
            if (value < minimum)
                return "must be >= " + std::to_string(minimum) + ", got " + text;
            if (value > maximum)
                return "must be <= " + std::to_string(maximum) + ", got " + text;
            return {};
        },
        rule);
}

CLI::Validator atLeast(std::int64_t minimum) {
    return inRange(minimum, std::numeric_limits<std::int64_t>::max());
}

/// --solver, the same for run and render: the model to run the scene in, instead of the
/// one its file names (so one scene file shows both).
void addSolverOption(CLI::App& command, std::string& solver) {
    const std::vector<std::string> names{jostle::toString(jostle::Solver::Classic),
                                         jostle::toString(jostle::Solver::Physical)};
    command.add_option("--solver", solver, "Run the scene in this model instead of its own")
        ->type_name("MODEL")
        ->check(CLI::IsMember(names));
}

/// Where the trace or the summary goes: stdout or a file of ours. Keeps the reason of the
/// first write that failed.
class Output {
public:
    /// Opens `path` ("-" is stdout); false, with errno set, if it cannot be created.
    bool open(const std::string& path) {
        if (path == "-") {
            out_ = stdout;
            return true;
        }
        errno = 0;
        file_.reset(std::fopen(path.c_str(), "w"));
        out_ = file_.get();
        return out_ != nullptr;
    }
    std::FILE* get() const { return out_; }
    bool isStdout() const { return out_ == stdout; }

    /// True while everything written has gone through. Called right after writing, so
    /// that errno still holds the reason of a failure.
    bool good() {
        if (error_ == 0 && std::ferror(out_))
            error_ = errno != 0 ? errno : EIO;
        return error_ == 0;
    }
    /// Flushes and closes; false if anything written was lost (error() says why).
    bool finish() {
        errno = 0;
        if (std::fflush(out_) != 0 && error_ == 0)
            error_ = errno != 0 ? errno : EIO;
        good();
        errno = 0;
        if (file_ && std::fclose(file_.release()) != 0 && error_ == 0)
            error_ = errno != 0 ? errno : EIO;
        return error_ == 0;
    }
    /// Why writing failed: an errno value.
    int error() const { return error_; }

private:
    struct Closer {
        void operator()(std::FILE* file) const { std::fclose(file); }
    };
    std::unique_ptr<std::FILE, Closer> file_;
    std::FILE* out_ = nullptr;
    int error_ = 0;
};

/// Reports that `what` ("the trace", "the summary") could not be written to `output`.
int writeFailed(const Output& output, const std::string& what, const std::string& path) {
    const std::string reason = systemMessage(output.error());
    if (output.isStdout())
        printError("cannot write " + what + " to standard output: " + reason);
    else
        printError(path + ": write failed: " + reason);
    return kFailure;
}

int run(const RunOptions& options) {
    const jostle::Scene scene = jostle::cli::loadScene(options.scene, options.solver);
    jostle::World world(scene.world);
    jostle::addTileMaps(world, scene); // the level first, then what moves in it
    const std::vector<jostle::BodyId> ids = jostle::addBodies(world, scene);

    const bool tracing = !options.trace.empty();
    Output output;
    if (!output.open(tracing ? options.trace : "-")) {
        printError(options.trace + ": cannot write: " + systemMessage(errno));
        return kBadInput;
    }
    std::vector<jostle::cli::TracedBody> traced;
    if (tracing) {
        // Static bodies never move: a trace of them would be the scene file again.
        for (std::size_t i = 0; i < ids.size(); ++i)
            if (scene.bodies[i].def.type != jostle::BodyType::Static)
                traced.push_back({ids[i], jostle::cli::csvField(scene.bodies[i].id)});
        jostle::cli::writeTraceHeader(output.get());
    }

    jostle::cli::Progress progress("jostle run", options.steps, output.isStdout() && tracing);
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t pairsLeftOut = 0;
    std::int64_t stepsLeavingOut = 0;
    // A trace that cannot be written ends the run: the steps after it would be lost.
    for (std::int64_t step = 1; step <= options.steps && output.good(); ++step) {
        world.step(scene.dt);
        pairsLeftOut += world.pairsLeftOut();
        stepsLeavingOut += world.pairsLeftOut() > 0 ? 1 : 0;
        if (tracing && step % options.every == 0)
            jostle::cli::writeTraceRows(output.get(), step, world, traced);
        progress.update(step);
    }
    const auto wallTime = std::chrono::steady_clock::now() - start;
    progress.erase();
    if (pairsLeftOut > 0)
        printWarning(options.scene + ": bodies piled on each other beyond the contact budget (" +
                     "physical.maxContactsPerBody): " + std::to_string(pairsLeftOut) +
                     " pairs left out in " + std::to_string(stepsLeavingOut) + " steps");

    if (!tracing && output.good()) {
        errno = 0;
        jostle::cli::printSummary(output.get(),
                                  {options.scene, scene, world, ids, options.steps, wallTime});
    }
    if (!output.finish())
        return writeFailed(output, tracing ? "the trace" : "the summary", options.trace);
    return 0;
}

/// What is wrong with the command line when its first word is neither a command nor
/// help, naming that word and the commands there are; empty when nothing is.
std::string commandProblem(CLI::App& app, int argc, char** argv) {
    const std::string first = argc > 1 ? argv[1] : "";
    std::string names;
    bool known = false;
    for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        names += (names.empty() ? "" : ", ") + command->get_name();
        known = known || command->check_name(first);
    }
    const std::string commands = " (commands: " + names + ")";
    if (argc < 2)
        return "a command is required" + commands;
    if (known || app.get_help_ptr()->check_name(first) || app.get_version_ptr()->check_name(first))
        return {};
    if (first.starts_with('-'))
        return "unknown option '" + first + "'" + commands;
    return "unknown command '" + first + "'" + commands;
}

/// Keeps the standard descriptors taken: one that is closed is opened on /dev/null the
/// other way round (input for writing, outputs for reading). So no file the program opens
/// takes its number, and writing to a closed standard output still fails, with EBADF.
void holdStandardDescriptors() {
    for (int descriptor = STDIN_FILENO; descriptor <= STDERR_FILENO; ++descriptor)
        if (::fcntl(descriptor, F_GETFD) == -1 && errno == EBADF)
            ::open("/dev/null", descriptor == STDIN_FILENO ? O_WRONLY : O_RDONLY);
}

} // namespace

int main(int argc, char** argv) {
    holdStandardDescriptors();
    CLI::App app{"jostle: 2D collision detection and response, from the command line.", "jostle"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "jostle " JOSTLE_VERSION_STRING);

    RunOptions options;
    CLI::App* runCommand =
        app.add_subcommand("run", "Load a scene file and step it; print a summary or a trace.");
    runCommand
        ->add_option(
            "scene", options.scene,
            "The scene file (docs/scene-format.md), or a Tiled map: .tmj, .tmx (docs/levels.md)")
        ->required();
    runCommand->add_option("-n,--steps", options.steps, "How many steps to take, >= 0")
        ->required()
        ->check(atLeast(0));
    CLI::Option* traceOption = runCommand->add_option(
        "--trace", options.trace,
        "Write a CSV trace (step,id,x,y,vx,vy) of the non-static bodies to FILE, or - for "
        "stdout");
    traceOption->type_name("FILE|-");
    runCommand->add_option("--every", options.every, "Trace only steps K, 2K, 3K, ... (K >= 1)")
        ->type_name("K")
        ->check(atLeast(1))
        ->needs(traceOption);
    addSolverOption(*runCommand, options.solver);

    jostle::cli::RenderOptions renderOptions;
    CLI::App* renderCommand = app.add_subcommand(
        "render", "Step a scene file headless and draw it: an animated GIF or a PNG.");
    renderCommand
        ->add_option(
            "scene", renderOptions.scene,
            "The scene file (docs/scene-format.md), or a Tiled map: .tmj, .tmx (docs/levels.md)")
        ->required();
    renderCommand
        ->add_option("-o,--out", renderOptions.out,
                     "The image to write: FILE.gif (every K-th step) or FILE.png (the last)")
        ->type_name("FILE")
        ->required();
    renderCommand->add_option("-n,--steps", renderOptions.steps, "How many steps to take, >= 0")
        ->capture_default_str()
        ->check(atLeast(0));
    const std::int64_t maxSide = jostle::cli::kMaxImageSide;
    renderCommand
        ->add_option("--width", renderOptions.width,
                     "Image width in pixels (default: 640, or fitted to --height)")
        ->type_name("W")
        ->check(inRange(1, maxSide));
    renderCommand
        ->add_option("--height", renderOptions.height,
                     "Image height in pixels (default: fitted to the scene and the width)")
        ->type_name("H")
        ->check(inRange(1, maxSide));
    renderCommand
        ->add_option("--every", renderOptions.every, "GIF: a frame of steps 0, K, 2K, ... (K >= 1)")
        ->type_name("K")
        ->capture_default_str()
        ->check(atLeast(1));
    addSolverOption(*renderCommand, renderOptions.solver);
    renderCommand->add_flag("--legend", renderOptions.legend,
                            "Draw a key to the colours in a band under the scene (the image "
                            "grows by its height)");
    renderCommand->add_flag("--debug", renderOptions.debug,
                            "Draw the debug marks too: contacts, velocities, the sides "
                            "touched, the broadphase's cells");

    jostle::cli::SyncTestOptions syncOptions;
    CLI::App* syncCommand = app.add_subcommand(
        "synctest", "Roll a scene back at every step and step it again: the same bits, or the "
                    "first step, body and field that differ (exit 1).");
    syncCommand
        ->add_option(
            "scene", syncOptions.scene,
            "The scene file (docs/scene-format.md), or a Tiled map: .tmj, .tmx (docs/levels.md)")
        ->required();
    syncCommand->add_option("-n,--steps", syncOptions.steps, "How many steps to take, >= 1")
        ->capture_default_str()
        ->check(atLeast(1));
    syncCommand
        ->add_option("-k,--rollback", syncOptions.rollback,
                     "How many steps each rollback goes back, 1 to 1000")
        ->capture_default_str()
        ->check(inRange(1, 1000));
    syncCommand->add_option("--workers", syncOptions.workers, "Threads to step on, 1 to 64")
        ->capture_default_str()
        ->check(inRange(1, 64));
    syncCommand
        ->add_option("--nudge", syncOptions.nudge,
                     "For testing the test: nudge a body by a bit when step S is stepped again")
        ->type_name("S")
        ->check(atLeast(1));
    addSolverOption(*syncCommand, syncOptions.solver);

    const auto badUsage = [](const std::string& message, const char* command) {
        printError(message);
        std::fprintf(stderr, "Run '%s --help' for usage.\n", command);
        return kBadInput;
    };
    // CLI11 says "A subcommand is required" whatever the first word is.
    if (const std::string problem = commandProblem(app, argc, argv); !problem.empty())
        return badUsage(problem, "jostle");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help is a ParseError that succeeds; CLI11 prints the help of the right command.
        if (error.get_exit_code() == 0)
            return app.exit(error);
        return badUsage(error.what(), runCommand->parsed()      ? "jostle run"
                                      : renderCommand->parsed() ? "jostle render"
                                      : syncCommand->parsed()   ? "jostle synctest"
                                                                : "jostle");
    }

    const std::string& scenePath = renderCommand->parsed() ? renderOptions.scene
                                   : syncCommand->parsed() ? syncOptions.scene
                                                           : options.scene;
    try {
        if (syncCommand->parsed())
            return jostle::cli::syncTest(syncOptions);
        return renderCommand->parsed() ? jostle::cli::render(renderOptions) : run(options);
    } catch (const jostle::SceneError& error) {
        printError(error.what()); // already names the file
        return kBadInput;
    } catch (const jostle::Error& error) {
        // The world refused the scene (e.g. a solver it does not have yet).
        printError(scenePath + ": " + error.what());
        return kBadInput;
    } catch (const std::exception& error) {
        printError(error.what());
        return kFailure;
    }
}
