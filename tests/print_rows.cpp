// jostle-test-rows: every row of every table of settings (tests/property_samples.hpp's
// forEachTable), for the tests in other languages that must see each one: bindings/lua/
// tests/test_rows.lua and bindings/web/tests/js_api.js. One row a line, as a JSON object
// or, with --lua, a Lua table (the whole output is then a chunk that returns the list):
//
//   {"table": "body", "name": "slope", "sample": [1, -1], "needs": {"type": "kinematic",
//    "hw": 1, "hh": 1}, "pointer": false, "file": true}
//
// table: the table's name (world, tasks, classic, physical, body, tileMap); sample: a value
// its rule accepts that is not its default; needs: what else a definition must hold to
// take it (a body's size, a ramp's type, a map's tile and rows); pointer: a pointer
// (userData), which no file holds; file: whether a scene file holds it.
#include "property_samples.hpp"

#include <cstdio>
#include <cstring>
#include <string>
#include <variant>
#include <vector>

namespace {

using namespace jostle;
using test_support::literalOf;

/// `text` in double quotes, a string in JSON and in Lua alike (names need no escapes).
std::string quoted(const std::string& text) {
    std::string out(1, '"');
    out += text;
    out += '"';
    return out;
}

/// A field of an object written in `notation`: "name": value, or name = value.
std::string member(const std::string& name, const std::string& value, Notation notation) {
    return (notation == Notation::Lua ? name + " = " : quoted(name) + ": ") + value;
}

/// An object of the members given (braces in JSON and in Lua alike).
std::string object(const std::vector<std::string>& members) {
    std::string text = "{";
    for (std::size_t i = 0; i < members.size(); ++i)
        text += (i ? ", " : "") + members[i];
    return text + "}";
}

/// What a definition must hold besides the field of `property` of table `table`.
std::vector<std::string> needsOf(const std::string& table, const properties::Property& property,
                                 Notation notation) {
    std::vector<std::string> needs;
    if (table == "body") {
        for (const auto& [need, value] : test_support::sampleNeeds(property))
            needs.push_back(member(need->name, literalOf(value, notation), notation));
        for (const char* size : {"hw", "hh"})
            if (std::strcmp(property.name, size) != 0)
                needs.push_back(member(size, "1", notation));
    } else if (table == "tileMap") {
        if (std::strcmp(property.name, "tile") != 0)
            needs.push_back(member("tile", "1", notation));
        needs.push_back(
            member("rows", notation == Notation::Lua ? "{\"#\"}" : "[\"#\"]", notation));
    }
    return needs;
}

} // namespace

int main(int argc, char** argv) {
    const Notation notation =
        argc > 1 && std::strcmp(argv[1], "--lua") == 0 ? Notation::Lua : Notation::Json;
    if (notation == Notation::Lua)
        std::printf("return {\n");
    test_support::forEachTable([&](const std::string& table, const auto& fields) {
        for (const auto& field : fields) {
            const properties::Property& property = *field.property;
            const bool pointer = std::holds_alternative<void*>(property.byDefault);
            const auto flag = [](bool on) { return std::string(on ? "true" : "false"); };
            const std::string row = object(
                {member("table", quoted(table), notation),
                 member("name", quoted(property.name), notation),
                 member("sample", literalOf(test_support::sampleOf(property), notation), notation),
                 member("needs", object(needsOf(table, property, notation)), notation),
                 member("pointer", flag(pointer), notation),
                 member("file", flag(!pointer && table != "tasks"), notation)});
            std::printf("%s%s\n", row.c_str(), notation == Notation::Lua ? "," : "");
        }
    });
    if (notation == Notation::Lua)
        std::printf("}\n");
    return 0;
}
