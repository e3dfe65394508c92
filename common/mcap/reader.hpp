#pragma once
// Reads an MCAP file front to back: checks the magic and header, decompresses each chunk and
// checks its CRC, hands every message over with its channel and schema, checks the data section
// CRC at the data end, then the summary (its CRC, and its statistics against what was read).
//
// A file whose writer was killed has no data end, summary or footer, and may end inside a
// record: reading then stops after the last complete record, every message before it is
// delivered and the report says where the file was cut. Malformed content and CRC mismatches
// throw McapError with the path and the byte offset.
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "common/mcap/records.hpp"

namespace autonomy::mcap {

struct ReadReport {
  bool complete = false;         // data end, summary, footer and trailing magic all read and checked
  bool truncated = false;        // the file ends inside a record
  uint64_t file_size = 0;
  uint64_t readable_until = 0;   // offset after the last complete record of the data section
  std::string note;              // why reading ended before a footer, when it did
  bool data_crc_checked = false;     // the data end carried a CRC and it matched
  bool summary_crc_checked = false;  // the footer carried a CRC and it matched
  uint64_t messages = 0;
  uint32_t chunks = 0;
  uint64_t chunk_compressed_bytes = 0;
  uint64_t chunk_uncompressed_bytes = 0;
  std::set<std::string> compressions;  // "" stands for uncompressed chunks
  std::optional<Statistics> summary_statistics;
  uint32_t summary_chunk_indexes = 0;
};

class Reader {
 public:
  using OnMessage = std::function<void(const Channel&, const Schema*, const Message&)>;

  // Opens path and reads magic and header; throws McapError when it is not an MCAP file.
  explicit Reader(const std::string& path);

  const Header& header() const { return header_; }
  // Reads the whole file (once per Reader); messages in file order.
  ReadReport read(const OnMessage& on_message);

  const std::map<uint16_t, Schema>& schemas() const { return schemas_; }
  const std::map<uint16_t, Channel>& channels() const { return channels_; }

 private:
  void records(std::string_view bytes, uint64_t base, const OnMessage& on_message, ReadReport& report);
  void summary(uint64_t data_end_offset, ReadReport& report);
  [[noreturn]] void fail(uint64_t offset, const std::string& what) const;

  std::string path_;
  std::ifstream in_;
  uint64_t size_ = 0;
  uint64_t header_end_ = 0;
  Header header_;
  std::map<uint16_t, Schema> schemas_;
  std::map<uint16_t, Channel> channels_;
};

}  // namespace autonomy::mcap
