#include "common/mcap/compression.hpp"

#include <zstd.h>

#include "common/mcap/records.hpp"

namespace autonomy::mcap {

bool compression_supported(std::string_view name) { return name.empty() || name == "zstd"; }

std::string compress(std::string_view name, std::string_view data, int level) {
  if (name.empty()) return std::string(data);
  if (name != "zstd") throw McapError("compression \"" + std::string(name) + "\" is not supported (use zstd or none)");
  std::string out(ZSTD_compressBound(data.size()), '\0');
  const size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), level);
  if (ZSTD_isError(n)) throw McapError(std::string("zstd compression failed: ") + ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

std::string decompress(std::string_view name, std::string_view data, uint64_t expected_size) {
  if (name.empty()) {
    if (data.size() != expected_size)
      throw McapError("uncompressed chunk holds " + std::to_string(data.size()) + " bytes, its header says " +
                      std::to_string(expected_size));
    return std::string(data);
  }
  if (name != "zstd")
    throw McapError("chunk compression \"" + std::string(name) + "\" is not supported by this reader (zstd or none)");
  std::string out(expected_size, '\0');
  const size_t n = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
  if (ZSTD_isError(n)) throw McapError(std::string("zstd decompression failed: ") + ZSTD_getErrorName(n));
  if (n != expected_size)
    throw McapError("chunk decompressed to " + std::to_string(n) + " bytes, its header says " +
                    std::to_string(expected_size));
  return out;
}

}  // namespace autonomy::mcap
