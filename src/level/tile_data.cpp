// Decoding a tile layer's data: base64, zlib and gzip (zlib's inflate, which reads both
// headers), CSV.
#include "tile_data.hpp"

#include "tiled_map.hpp"

#ifndef JOSTLE_LEVEL_JSON_ONLY
#include <zlib.h>
#include <zstd.h>
#endif

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace jostle::tiled {

namespace {

/// The bytes of base64 text; whitespace between groups is allowed (TMX indents its data).
std::string fromBase64(std::string_view text) {
    static const std::array<int, 256> kValue = [] {
        std::array<int, 256> value{};
        value.fill(-1);
        const std::string_view alphabet =
            "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        for (std::size_t i = 0; i < alphabet.size(); ++i)
            value[static_cast<unsigned char>(alphabet[i])] = static_cast<int>(i);
        return value;
    }();
    std::string bytes;
    bytes.reserve(text.size() / 4 * 3);
    unsigned bits = 0;
    int held = 0;
    bool ended = false;
    for (const char c : text) {
        if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
            continue;
        if (c == '=') {
            ended = true;
            continue;
        }
        const int value = kValue[static_cast<unsigned char>(c)];
        if (value < 0 || ended)
            throw std::runtime_error(std::string("data: not base64: '") + c + "'");
        bits = (bits << 6) | static_cast<unsigned>(value);
        held += 6;
        if (held >= 8) {
            held -= 8;
            bytes.push_back(static_cast<char>((bits >> held) & 0xFFu));
        }
    }
    return bytes;
}

/// zlib or gzip data inflated into exactly `size` bytes.
std::string inflateExactly(const std::string& packed, std::size_t size,
                           std::string_view compression) {
#ifdef JOSTLE_LEVEL_JSON_ONLY
    (void)packed;
    (void)size;
    throw std::runtime_error(
        "data: " + std::string(compression) +
        " compression is not read in this build (save the map with base64 or CSV data)");
#else
    std::string bytes(size, '\0');
    z_stream stream{};
    // 15 + 32: a zlib or a gzip header, whichever it is.
    if (inflateInit2(&stream, 15 + 32) != Z_OK)
        throw std::runtime_error("data: zlib could not start");
    stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.data()));
    stream.avail_in = static_cast<uInt>(packed.size());
    stream.next_out = reinterpret_cast<Bytef*>(bytes.data());
    stream.avail_out = static_cast<uInt>(bytes.size());
    const int result = inflate(&stream, Z_FINISH);
    const std::size_t written = bytes.size() - stream.avail_out;
    inflateEnd(&stream);
    if (result != Z_STREAM_END || written != size)
        throw std::runtime_error("data: not " + std::string(compression) + " data of " +
                                 std::to_string(size / 4) + " tiles" +
                                 (result == Z_BUF_ERROR ? " (it holds more)" : ""));
    return bytes;
#endif
}

/// zstd data decompressed into exactly `size` bytes.
std::string unzstdExactly(const std::string& packed, std::size_t size) {
#ifdef JOSTLE_LEVEL_JSON_ONLY
    (void)packed;
    (void)size;
    throw std::runtime_error(
        "data: zstd compression is not read in this build (save the map with base64 or CSV data)");
#else
    std::string bytes(size, '\0');
    const std::size_t written =
        ZSTD_decompress(bytes.data(), bytes.size(), packed.data(), packed.size());
    if (ZSTD_isError(written) || written != size)
        throw std::runtime_error("data: not zstd data of " + std::to_string(size / 4) + " tiles");
    return bytes;
#endif
}

} // namespace

std::vector<std::uint32_t> decodeBase64Gids(std::string_view text, std::string_view compression,
                                            std::size_t count) {
    if (count > (std::size_t{1} << 26))
        throw std::runtime_error("data: more than 2^26 tiles");
    std::string bytes = fromBase64(text);
    if (compression == "zlib" || compression == "gzip")
        bytes = inflateExactly(bytes, 4 * count, compression);
    else if (compression == "zstd")
        bytes = unzstdExactly(bytes, 4 * count);
    else if (!compression.empty())
        throw std::runtime_error("data: unknown compression \"" + std::string(compression) + "\"");
    if (bytes.size() != 4 * count)
        throw std::runtime_error("data: " + std::to_string(bytes.size() / 4) + " tiles, expected " +
                                 std::to_string(count));
    std::vector<std::uint32_t> gids(count);
    for (std::size_t i = 0; i < count; ++i) {
        const auto byte = [&](std::size_t k) {
            return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[4 * i + k]));
        };
        gids[i] = byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
    }
    return gids;
}

std::optional<int> wholeNumber(double value) {
    if (!(value >= INT32_MIN && value <= INT32_MAX) || value != std::trunc(value))
        return std::nullopt;
    return static_cast<int>(value);
}

std::optional<std::uint32_t> tileIdOf(double value) {
    if (!(value >= 0 && value <= 4294967295.0) || value != std::trunc(value))
        return std::nullopt;
    return static_cast<std::uint32_t>(value);
}

std::size_t cellCount(int width, int height) {
    if (width < 0 || height < 0 || static_cast<double>(width) * height > double(1 << 26))
        throw std::runtime_error(
            "width and height: expected at least 0, and 2^26 tiles at most, got " +
            std::to_string(width) + " x " + std::to_string(height));
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

void gatherChunks(const std::vector<Chunk>& chunks, Layer& layer) {
    long long left = INT32_MAX, top = INT32_MAX, right = INT32_MIN, bottom = INT32_MIN;
    for (const Chunk& chunk : chunks) {
        left = std::min<long long>(left, chunk.x);
        top = std::min<long long>(top, chunk.y);
        right = std::max<long long>(right, static_cast<long long>(chunk.x) + chunk.width);
        bottom = std::max<long long>(bottom, static_cast<long long>(chunk.y) + chunk.height);
    }
    if (chunks.empty())
        left = top = right = bottom = 0;
    if (static_cast<double>(right - left) * static_cast<double>(bottom - top) > double(1 << 26))
        throw std::runtime_error("chunks: more than 2^26 tiles in their bounds");
    layer.left = static_cast<int>(left);
    layer.top = static_cast<int>(top);
    layer.width = static_cast<int>(right - left);
    layer.height = static_cast<int>(bottom - top);
    const auto columns = static_cast<std::size_t>(layer.width);
    layer.gids.assign(cellCount(layer.width, layer.height), 0);
    for (const Chunk& chunk : chunks)
        for (std::size_t row = 0; row < static_cast<std::size_t>(chunk.height); ++row)
            for (std::size_t column = 0; column < static_cast<std::size_t>(chunk.width); ++column)
                layer.gids[(static_cast<std::size_t>(chunk.y - layer.top) + row) * columns +
                           static_cast<std::size_t>(chunk.x - layer.left) + column] =
                    chunk.gids[row * static_cast<std::size_t>(chunk.width) + column];
}

std::vector<std::uint32_t> decodeCsvGids(std::string_view text, std::size_t count) {
    std::vector<std::uint32_t> gids;
    gids.reserve(count);
    std::size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() &&
               (text[i] == ' ' || text[i] == '\n' || text[i] == '\r' || text[i] == '\t'))
            ++i;
        if (i == text.size())
            break;
        std::uint64_t value = 0;
        const std::size_t start = i;
        while (i < text.size() && text[i] >= '0' && text[i] <= '9') {
            value = value * 10 + static_cast<std::uint64_t>(text[i] - '0');
            if (value > 0xFFFFFFFFu)
                throw std::runtime_error("data: a tile id past 32 bits");
            ++i;
        }
        if (i == start)
            throw std::runtime_error(std::string("data: expected a tile id, got '") + text[i] +
                                     "'");
        gids.push_back(static_cast<std::uint32_t>(value));
        while (i < text.size() &&
               (text[i] == ' ' || text[i] == '\n' || text[i] == '\r' || text[i] == '\t'))
            ++i;
        if (i < text.size() && text[i] == ',')
            ++i;
    }
    if (gids.size() != count)
        throw std::runtime_error("data: " + std::to_string(gids.size()) + " tiles, expected " +
                                 std::to_string(count));
    return gids;
}

} // namespace jostle::tiled
