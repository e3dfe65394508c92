#pragma once
// Writes an MCAP file: magic, header, chunks of schema, channel and message records (compressed),
// a message index per channel after each chunk, then on close() the data end (with the data
// section CRC), the summary (schemas, channels, statistics, chunk indexes), the summary offsets
// and the footer (with the summary CRC).
//
// Each chunk reaches the file with one write(2) when it is closed, so a writer killed with -9
// leaves a file whose complete chunks a reader can read (see Reader): call flush_chunk() as often
// as losing the open chunk would matter (the recorder does every second).
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "common/mcap/crc32.hpp"
#include "common/mcap/records.hpp"

namespace autonomy::mcap {

struct WriterOptions {
  std::string profile;                     // "" or "x-..." (no well-known profile fits DDS)
  std::string library = "autonomy-mcap";   // the Header's free-form library field
  std::string compression = "zstd";        // "zstd" or "" (none)
  int compression_level = 3;
  uint64_t chunk_size = 1 << 20;           // a chunk closes once its records pass this size
};

class Writer {
 public:
  // Creates (truncates) path; throws McapError naming it when it cannot.
  Writer(const std::string& path, WriterOptions options = {});
  ~Writer();  // closes the file properly if close() was not called (errors are swallowed)
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // Ids are assigned from 1 (schemas) and 0 (channels) in call order.
  uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  uint16_t add_channel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                       const std::map<std::string, std::string>& metadata);

  // m.channel_id must come from add_channel.
  void write(const Message& m);
  // Writes the open chunk, if it holds anything, and its message indexes to the file.
  void flush_chunk();
  // Writes the rest of the file; further calls do nothing. Throws McapError on a write error.
  void close();

  const Statistics& statistics() const { return stats_; }
  uint64_t bytes_written() const { return offset_; }

 private:
  void write_out(const std::string& bytes, bool data_section);

  std::string path_;
  WriterOptions options_;
  int fd_ = -1;
  uint64_t offset_ = 0;
  Crc32 data_crc_;

  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  Statistics stats_;
  std::vector<ChunkIndex> chunk_indexes_;

  // The open chunk.
  std::string chunk_records_;
  std::map<uint16_t, MessageIndex> chunk_index_;
  uint64_t chunk_start_ = 0, chunk_end_ = 0;
  bool chunk_has_messages_ = false;
};

}  // namespace autonomy::mcap
