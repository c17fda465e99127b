// `jostle render`: see render.hpp. The drawing rules are documented in
// docs/scene-format.md; the camera's in camera.hpp.
#include "render.hpp"

#include "camera.hpp"
#include "canvas.hpp"
#include "canvas_draw.hpp"
#include "errors.hpp"
#include "image_files.hpp"
#include "legend.hpp"
#include "load_scene.hpp"
#include "progress.hpp"

#include "jostle/scene.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace jostle::cli {

namespace {

enum class ImageType { Gif, Png };

bool endsWith(const std::string& text, const std::string& suffix) {
    if (text.size() < suffix.size())
        return false;
    return std::equal(suffix.rbegin(), suffix.rend(), text.rbegin(), [](char a, char b) {
        return a == std::tolower(static_cast<unsigned char>(b));
    });
}

// The palette: the background, then for each body type (static, kinematic, dynamic, as
// BodyType numbers them) its fill and outline awake, and its fill and outline asleep, in
// the library's colours and by its rules (jostle::DebugPalette); the key's line and words
// (--legend); then the other colours World::debugDraw draws shapes with.
constexpr Rgb kBackground{24, 26, 33};

// The key's words, and the line between it and the scene: the demo's text and pane border
// (demo/palette.hpp).
constexpr Rgb kLegendText{230, 230, 230};
constexpr Rgb kLegendLine{60, 64, 76};
constexpr LegendColours kLegendColours{0, 13, 14};

/// The pixels of marks with no length of their own: a segment's tick.
constexpr double kMarkPixels = 8.0;

Rgb rgb(Colour c) {
    return {c.r, c.g, c.b};
}

std::vector<Rgb> makePalette() {
    const DebugPalette colours;
    std::vector<Rgb> palette{kBackground};
    for (BodyType type : {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic})
        for (bool asleep : {false, true}) {
            const Colour fill = colours.fillOf(type, asleep);
            palette.push_back(rgb(fill));
            palette.push_back(rgb(colours.outlineOf(fill)));
        }
    palette.push_back(kLegendLine); // 13
    palette.push_back(kLegendText); // 14
    for (Colour colour : {colours.bulletOutline, colours.oneWayFace, colours.contact,
                          colours.velocity, colours.touching, colours.gridCell, colours.gridBox})
        palette.push_back(rgb(colour));
    return palette;
}

std::uint8_t fillIndex(BodyType type, bool sleeping) {
    return static_cast<std::uint8_t>(1 + 4 * static_cast<int>(type) + (sleeping ? 2 : 0));
}

/// The key to what the scene shows at the start: each body type it has, sleeping where
/// bodies can fall asleep (the physical model with sleeping on), and sensors, outlined in
/// the colour of the first one's type.
std::vector<LegendEntry> legendEntries(const World& world) {
    std::array<bool, 3> types{};
    std::optional<BodyType> sensorType;
    for (BodyId body : world.bodies()) {
        const BodyType type = world.type(body);
        if (!world.isSensor(body))
            types[static_cast<std::size_t>(type)] = true;
        else if (!sensorType)
            sensorType = type;
    }
    static constexpr std::array<const char*, 3> kWords{"static", "kinematic", "dynamic"};
    std::vector<LegendEntry> entries;
    for (int type = 0; type < 3; ++type)
        if (types[static_cast<std::size_t>(type)]) {
            const std::uint8_t fill = fillIndex(static_cast<BodyType>(type), false);
            entries.push_back({fill, static_cast<std::uint8_t>(fill + 1),
                               kWords[static_cast<std::size_t>(type)]});
        }
    const bool dynamic = types[static_cast<std::size_t>(BodyType::Dynamic)];
    if ((dynamic || types[static_cast<std::size_t>(BodyType::Kinematic)]) &&
        world.solver() == Solver::Physical && world.sleeping()) {
        const std::uint8_t fill =
            fillIndex(dynamic ? BodyType::Dynamic : BodyType::Kinematic, true);
        entries.push_back({fill, static_cast<std::uint8_t>(fill + 1), "asleep"});
    }
    if (sensorType)
        entries.push_back({std::nullopt, fillIndex(*sensorType, false), "sensor"});
    return entries;
}

WorldBox boxOf(const World& world, BodyId body) {
    return {world.position(body), world.halfExtents(body)};
}

/// The view of every body (tile maps are bodies too), or of a 2 × 2 box around the
/// origin in a world without any.
View viewOf(const World& world) {
    std::vector<WorldBox> boxes;
    for (BodyId body : world.bodies())
        boxes.push_back(boxOf(world, body));
    return View::of(boxes);
}

/// The side not given, from the one given and the shape of the view: 1 to kMaxImageSide.
int fittedSide(double givenSide, double givenSpan, double otherSpan) {
    const double side = std::round(givenSide * otherSpan / givenSpan);
    if (!(side >= 1.0)) // also what is not a number
        return 1;
    return static_cast<int>(std::min(side, static_cast<double>(kMaxImageSide)));
}

void imageSize(const RenderOptions& options, const View& view, int& width, int& height) {
    width = static_cast<int>(options.width);
    height = static_cast<int>(options.height);
    if (width == 0 && height == 0)
        width = kDefaultImageWidth;
    if (height == 0)
        height = fittedSide(width, view.width(), view.height());
    else if (width == 0)
        width = fittedSide(height, view.height(), view.width());
}

/// The world's shapes as the library draws them (World::debugDraw), in this palette; with
/// `debug`, its marks too.
void draw(Canvas& canvas, const Camera& camera, const World& world, std::span<const Rgb> palette,
          bool debug) {
    canvas.clear(0);
    CanvasDraw drawing(canvas, camera, palette);
    world.debugDraw(drawing, {.contacts = debug,
                              .velocities = debug,
                              .touching = debug,
                              .grid = debug,
                              .markLength = static_cast<float>(kMarkPixels / camera.scale())});
}

/// A GIF frame's delay: the simulated time between frames, in the centiseconds GIF counts
/// in; at least 2, as browsers show shorter delays as 10.
int frameDelay(const Scene& scene, std::int64_t every) {
    const double centiseconds =
        std::round(static_cast<double>(scene.dt) * 100.0 * static_cast<double>(every));
    return static_cast<int>(std::clamp(centiseconds, 2.0, 65535.0));
}

struct FileCloser {
    void operator()(std::FILE* file) const { std::fclose(file); }
};

} // namespace

int render(const RenderOptions& options) {
    ImageType imageType = ImageType::Gif;
    if (endsWith(options.out, ".png"))
        imageType = ImageType::Png;
    else if (!endsWith(options.out, ".gif")) {
        printError("--out: " + options.out +
                   ": unknown image type: expected a name ending in .gif or .png");
        return kBadInput;
    }

    const Scene scene = loadScene(options.scene, options.solver);
    World world(scene.world);
    addTileMaps(world, scene);
    addBodies(world, scene);

    const View view = viewOf(world);
    int width = 0;
    int height = 0;
    imageSize(options, view, width, height);
    const Camera camera(view, width, height);
    const Legend legend(options.legend ? legendEntries(world) : std::vector<LegendEntry>{}, width);
    const int sceneHeight = height;
    height += legend.height();
    Canvas canvas(width, height);
    const std::vector<Rgb> palette = makePalette();
    const auto drawFrame = [&] {
        draw(canvas, camera, world, palette, options.debug);
        legend.draw(canvas, sceneHeight, kLegendColours);
    };

    if (imageType == ImageType::Png) {
        errno = 0;
        std::unique_ptr<std::FILE, FileCloser> file(std::fopen(options.out.c_str(), "wb"));
        if (!file) {
            printError(options.out + ": cannot write: " + systemMessage(errno));
            return kBadInput;
        }
        Progress progress("jostle render", options.steps, false);
        for (std::int64_t step = 1; step <= options.steps; ++step) {
            world.step(scene.dt);
            progress.update(step);
        }
        progress.erase();
        drawFrame();
        std::string error = writePng(file.get(), canvas, palette);
        errno = 0;
        if (std::fclose(file.release()) != 0 && error.empty())
            error = systemMessage(errno);
        if (!error.empty()) {
            printError(options.out + ": write failed: " + error);
            return kFailure;
        }
        return 0;
    }

    GifWriter gif;
    if (const std::string error = gif.open(options.out, width, height, palette); !error.empty()) {
        printError(options.out + ": cannot write: " + error);
        return kBadInput;
    }
    const int delay = frameDelay(scene, options.every);
    std::string error;
    Progress progress("jostle render", options.steps, false);
    for (std::int64_t step = 0; step <= options.steps && error.empty(); ++step) {
        if (step > 0)
            world.step(scene.dt);
        if (step % options.every == 0) {
            drawFrame();
            error = gif.addFrame(canvas, delay);
        }
        progress.update(step);
    }
    progress.erase();
    if (error.empty())
        error = gif.close();
    if (!error.empty()) {
        printError(options.out + ": write failed: " + error);
        return kFailure;
    }
    return 0;
}

} // namespace jostle::cli
