#pragma once
// Chunk compression: "zstd" (libzstd, Debian's libzstd-dev) or "" (none). Other names (lz4)
// are refused with the name in the message.
#include <string>
#include <string_view>

namespace autonomy::mcap {

bool compression_supported(std::string_view name);
std::string compress(std::string_view name, std::string_view data, int level);
// Throws McapError when the data does not decompress to exactly expected_size bytes.
std::string decompress(std::string_view name, std::string_view data, uint64_t expected_size);

}  // namespace autonomy::mcap
