// A tile layer's data as Tiled writes it: CSV, or base64 of little-endian 32-bit global
// ids, plain or compressed by zlib, gzip or zstd (not in the WebAssembly build).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace jostle::tiled {

/// The `count` global ids of a base64 text, decompressed as `compression` says ("",
/// "zlib", "gzip" or "zstd"). Throws std::runtime_error saying what is wrong.
std::vector<std::uint32_t> decodeBase64Gids(std::string_view text, std::string_view compression,
                                            std::size_t count);

/// The global ids of a CSV text ("1,2,0,\n3,..."), which must be `count`.
std::vector<std::uint32_t> decodeCsvGids(std::string_view text, std::size_t count);

} // namespace jostle::tiled
