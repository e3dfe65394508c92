#pragma once
// CRC-32 as MCAP uses it (zlib's: reflected polynomial 0xEDB88320, initial and final xor
// 0xFFFFFFFF), computed incrementally so that a writer can checksum a section as it streams it.
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace autonomy::mcap {

class Crc32 {
 public:
  void update(const void* data, size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
  uint32_t value() const { return state_ ^ 0xFFFFFFFFu; }

 private:
  uint32_t state_ = 0xFFFFFFFFu;
};

uint32_t crc32(const void* data, size_t size);
inline uint32_t crc32(std::string_view bytes) { return crc32(bytes.data(), bytes.size()); }

}  // namespace autonomy::mcap
