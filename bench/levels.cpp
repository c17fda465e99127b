// jostle-bench-levels: how long loading a Tiled map takes (issue 34: a 512 x 512 tile map in
// 30 ms at most, a platformer level of 200 x 40 tiles and 100 objects in 2 ms): maps made
// here in each format and encoding Tiled writes, loaded by jostle::loadTiled, the median
// of several loads each, with the time per tile.
//   jostle-bench-levels [--runs N] [--dir DIR]
#include "jostle/level.hpp"

#include "timing.hpp"

#include <CLI/CLI.hpp>

#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

/// Base64 of bytes.
std::string base64(const std::string& bytes) {
    static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const auto b = [&](std::size_t k) { return static_cast<unsigned>(static_cast<unsigned char>(bytes[i + k])); };
        const unsigned v = b(0) << 16 | b(1) << 8 | b(2);
        for (int s = 18; s >= 0; s -= 6)
            out += kAlphabet[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        const unsigned v = static_cast<unsigned>(static_cast<unsigned char>(bytes[i])) << 16 |
                           (i + 1 < bytes.size() ? static_cast<unsigned>(static_cast<unsigned char>(bytes[i + 1])) << 8 : 0u);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

/// A level's tiles: a floor, walls, and platforms every 6 rows, the rest empty; tile 1
/// solid, tile 2 one-way, by property.
std::vector<std::uint32_t> tilesOf(int columns, int rows) {
    std::vector<std::uint32_t> gids(static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows), 0);
    for (int row = 0; row < rows; ++row)
        for (int column = 0; column < columns; ++column) {
            std::uint32_t gid = 0;
            if (row == rows - 1 || column == 0 || column == columns - 1)
                gid = 1;
            else if (row % 6 == 5 && (column / 8) % 2 == 0)
                gid = (column / 16) % 2 == 0 ? 1 : 2;
            gids[static_cast<std::size_t>(row) * static_cast<std::size_t>(columns) + static_cast<std::size_t>(column)] = gid;
        }
    return gids;
}

/// A Tiled JSON map of `columns` x `rows` tiles and `objects` crates, its layer data in
/// `encoding` ("array" or "zlib").
std::string jsonMap(int columns, int rows, int objects, const std::string& encoding) {
    const std::vector<std::uint32_t> gids = tilesOf(columns, rows);
    std::string data;
    if (encoding == "zlib") {
        std::string raw;
        for (const std::uint32_t gid : gids)
            for (int k = 0; k < 4; ++k)
                raw += static_cast<char>((gid >> (8 * k)) & 0xFF);
        uLongf size = compressBound(static_cast<uLong>(raw.size()));
        std::string packed(size, '\0');
        compress(reinterpret_cast<Bytef*>(packed.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                 static_cast<uLong>(raw.size()));
        packed.resize(size);
        data = "\"encoding\": \"base64\", \"compression\": \"zlib\", \"data\": \"" + base64(packed) + "\"";
    } else {
        data = "\"data\": [";
        for (std::size_t i = 0; i < gids.size(); ++i)
            data += (i ? "," : "") + std::to_string(gids[i]);
        data += "]";
    }
    std::string things;
    for (int i = 0; i < objects; ++i)
        things += std::string(i ? "," : "") + "{\"id\": " + std::to_string(i + 1) + ", \"name\": \"crate\", \"x\": " +
                  std::to_string(16 + 16 * (i % (columns - 2))) + ", \"y\": 16, \"width\": 16, \"height\": 16, " +
                  "\"properties\": [{\"name\": \"friction\", \"type\": \"float\", \"value\": 0.3}]}";
    return "{\"orientation\": \"orthogonal\", \"tilewidth\": 16, \"tileheight\": 16, \"width\": " +
           std::to_string(columns) + ", \"height\": " + std::to_string(rows) +
           ", \"properties\": [{\"name\": \"gravityY\", \"type\": \"float\", \"value\": 800}]," +
           " \"tilesets\": [{\"firstgid\": 1, \"name\": \"tiles\", \"tilewidth\": 16, \"tileheight\": 16, " +
           "\"tilecount\": 2, \"tiles\": [{\"id\": 0, \"properties\": [{\"name\": \"collision\", \"type\": " +
           "\"string\", \"value\": \"solid\"}]}, {\"id\": 1, \"properties\": [{\"name\": \"collision\", " +
           "\"type\": \"string\", \"value\": \"oneWay\"}]}]}], \"layers\": [{\"type\": \"tilelayer\", \"name\": " +
           "\"ground\", \"width\": " + std::to_string(columns) + ", \"height\": " + std::to_string(rows) + ", " +
           data + "}, {\"type\": \"objectgroup\", \"name\": \"things\", \"objects\": [" + things + "]}]}";
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app("How long loading a Tiled map takes (jostle::loadTiled).");
    int runs = 11;
    std::string dir = (std::filesystem::temp_directory_path() / "jostle-bench-levels").string();
    app.add_option("--runs", runs, "loads timed, the median kept")->check(CLI::PositiveNumber);
    app.add_option("--dir", dir, "where the maps are written");
    CLI11_PARSE(app, argc, argv);
    std::filesystem::create_directories(dir);

    struct Case {
        const char* name;
        int columns, rows, objects;
        const char* encoding;
    };
    const Case cases[] = {{"512 x 512, JSON array", 512, 512, 0, "array"},
                          {"512 x 512, base64 + zlib", 512, 512, 0, "zlib"},
                          {"200 x 40 + 100 objects, JSON array", 200, 40, 100, "array"},
                          {"200 x 40 + 100 objects, base64 + zlib", 200, 40, 100, "zlib"}};
    std::printf("| map | tiles | bytes | load ms | ns a tile |\n|---|---:|---:|---:|---:|\n");
    for (const Case& c : cases) {
        const std::string path = dir + "/map_" + std::to_string(c.columns) + "_" + c.encoding + ".tmj";
        std::ofstream(path) << jsonMap(c.columns, c.rows, c.objects, c.encoding);
        const double us = jostle::bench::medianMicroseconds(runs, [&] { jostle::loadTiled(path); });
        const double tiles = static_cast<double>(c.columns) * c.rows;
        std::printf("| %s | %.0f | %ju | %.2f | %.1f |\n", c.name, tiles,
                    static_cast<std::uintmax_t>(std::filesystem::file_size(path)), us / 1000, us * 1000 / tiles);
    }
}
