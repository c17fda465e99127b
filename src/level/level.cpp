// Loading a level: the file and the tilesets beside it read, the format told by the text,
// and the objects found by name.
#include "level_rules.hpp"
#include "tiled_level.hpp"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <variant>

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

/// The kind of value a property holds, as messages name it.
const char* kindOf(const PropertyValue& value) {
    static constexpr const char* kKinds[] = {"a flag", "a number", "text"};
    static_assert(std::variant_size_v<PropertyValue> == std::size(kKinds));
    return kKinds[value.index()];
}

/// Object `object`'s property `name` as a T, or null if it has none; throws SceneError for
/// one of another kind.
template <class T> const T* propertyOf(const LevelObject& object, const std::string& name) {
    const auto found = object.properties.find(name);
    if (found == object.properties.end())
        return nullptr;
    if (const T* value = std::get_if<T>(&found->second))
        return value;
    throw SceneError("object " + level::quoted(object.name) + ": property " + level::quoted(name) +
                     ": expected " + kindOf(PropertyValue(T{})) + ", got " + kindOf(found->second));
}

template <class T> const T& requiredProperty(const LevelObject& object, const std::string& name) {
    if (const T* value = propertyOf<T>(object, name))
        return *value;
    throw SceneError("object " + level::quoted(object.name) + ": no property " +
                     level::quoted(name));
}

template <class T>
T propertyOr(const LevelObject& object, const std::string& name, const T& otherwise) {
    const T* value = propertyOf<T>(object, name);
    return value ? *value : otherwise;
}

} // namespace

double LevelObject::number(const std::string& property) const {
    return requiredProperty<double>(*this, property);
}
bool LevelObject::flag(const std::string& property) const {
    return requiredProperty<bool>(*this, property);
}
const std::string& LevelObject::text(const std::string& property) const {
    return requiredProperty<std::string>(*this, property);
}
double LevelObject::number(const std::string& property, double otherwise) const {
    return propertyOr(*this, property, otherwise);
}
bool LevelObject::flag(const std::string& property, bool otherwise) const {
    return propertyOr(*this, property, otherwise);
}
std::string LevelObject::text(const std::string& property, const std::string& otherwise) const {
    return propertyOr(*this, property, otherwise);
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
