// Loading a level: the file and the tilesets beside it read, the format told by the text,
// and the objects found by name.
#include "tiled_level.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace jostle {

const LevelObject* Level::find(std::string_view name) const {
    for (const LevelObject& object : objects)
        if (object.name == name)
            return &object;
    return nullptr;
}

std::vector<const LevelObject*> Level::all(std::string_view name) const {
    std::vector<const LevelObject*> found;
    for (const LevelObject& object : objects)
        if (object.name == name)
            found.push_back(&object);
    return found;
}

namespace {

std::string readWhole(const std::string& path, const std::string& shown) {
    std::ifstream file(path, std::ios::binary);
    if (!file)
        throw SceneError(shown + ": cannot read the file");
    std::ostringstream text;
    text << file.rdbuf();
    if (text.str().size() > kMaxSceneBytes)
        throw SceneError(shown + ": larger than 1 GiB");
    return text.str();
}

bool isXml(std::string_view text) {
    const std::size_t start = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    return start != std::string_view::npos && text[start] == '<';
}

/// Reads a file a map or project names, beside it.
FileReader besideFile(const std::string& path) {
    const std::filesystem::path directory = std::filesystem::path(path).parent_path();
    return [directory](const std::string& source) {
        return readWhole((directory / source).string(), source);
    };
}

} // namespace

Level parseTiled(std::string_view text, const std::string& name, const FileReader& readFile) {
#ifdef JOSTLE_LEVEL_JSON_ONLY
    if (isXml(text))
        throw SceneError(
            name + ": XML maps (.tmx) are not read in this build: export the map as JSON (.tmj)");
    return tiled::toLevel(tiled::readJson(text, name, readFile), name);
#else
    return tiled::toLevel(isXml(text) ? tiled::readTmx(text, name, readFile)
                                      : tiled::readJson(text, name, readFile),
                          name);
#endif
}

Level loadTiled(const std::string& path) {
    return parseTiled(readWhole(path, path), path, besideFile(path));
}

Level loadLdtk(const std::string& path, const std::string& level, const IntGridKinds& kinds) {
    return parseLdtk(readWhole(path, path), path, level, besideFile(path), kinds);
}

} // namespace jostle
