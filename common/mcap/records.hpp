#pragma once
// MCAP records (https://mcap.dev/spec, major version 0) as plain structs, and their byte layout:
// every record is <opcode u8><content length u64><content>, integers little-endian, strings and
// maps with a u32 byte length. Only the records this project writes or reads are here
// (attachments and metadata are recognised by opcode and skipped).
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace autonomy::mcap {

inline constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

enum class Op : uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Attachment = 0x09,
  AttachmentIndex = 0x0A,
  Statistics = 0x0B,
  Metadata = 0x0C,
  MetadataIndex = 0x0D,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};
const char* to_string(Op op);

// A malformed file or a failed check, with the byte offset where it was found.
class McapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Header {
  std::string profile;
  std::string library;
};

struct Footer {
  uint64_t summary_start = 0;
  uint64_t summary_offset_start = 0;
  uint32_t summary_crc = 0;
};

struct Schema {
  uint16_t id = 0;
  std::string name;
  std::string encoding;
  std::string data;
};

struct Channel {
  uint16_t id = 0;
  uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;
  std::map<std::string, std::string> metadata;
};

struct Message {
  uint16_t channel_id = 0;
  uint32_t sequence = 0;
  uint64_t log_time = 0;
  uint64_t publish_time = 0;
  std::string data;
};

struct Chunk {
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  uint64_t uncompressed_size = 0;
  uint32_t uncompressed_crc = 0;
  std::string compression;
  std::string records;  // as stored (compressed when compression is not "")
};

struct MessageIndex {
  uint16_t channel_id = 0;
  std::vector<std::pair<uint64_t, uint64_t>> records;  // (log_time, offset in the uncompressed chunk)
};

struct ChunkIndex {
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  uint64_t chunk_start_offset = 0;
  uint64_t chunk_length = 0;
  std::map<uint16_t, uint64_t> message_index_offsets;
  uint64_t message_index_length = 0;
  std::string compression;
  uint64_t compressed_size = 0;
  uint64_t uncompressed_size = 0;
};

struct Statistics {
  uint64_t message_count = 0;
  uint16_t schema_count = 0;
  uint32_t channel_count = 0;
  uint32_t attachment_count = 0;
  uint32_t metadata_count = 0;
  uint32_t chunk_count = 0;
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  std::map<uint16_t, uint64_t> channel_message_counts;
};

struct SummaryOffset {
  Op group_opcode = Op::Schema;
  uint64_t group_start = 0;
  uint64_t group_length = 0;
};

struct DataEnd {
  uint32_t data_section_crc = 0;
};

// Appends one whole record (opcode, length, content) to out.
void append(std::string& out, const Header& r);
void append(std::string& out, const Footer& r);
void append(std::string& out, const Schema& r);
void append(std::string& out, const Channel& r);
void append(std::string& out, const Message& r);
void append(std::string& out, const Chunk& r);
void append(std::string& out, const MessageIndex& r);
void append(std::string& out, const ChunkIndex& r);
void append(std::string& out, const Statistics& r);
void append(std::string& out, const SummaryOffset& r);
void append(std::string& out, const DataEnd& r);

// Parse one record's content (without opcode and length). Throws McapError naming the record
// and the field that runs past the content. Fields added by later versions of the format are
// ignored, as the specification asks.
Header parse_header(std::string_view content);
Footer parse_footer(std::string_view content);
Schema parse_schema(std::string_view content);
Channel parse_channel(std::string_view content);
Message parse_message(std::string_view content);
Chunk parse_chunk(std::string_view content);
MessageIndex parse_message_index(std::string_view content);
ChunkIndex parse_chunk_index(std::string_view content);
Statistics parse_statistics(std::string_view content);
SummaryOffset parse_summary_offset(std::string_view content);
DataEnd parse_data_end(std::string_view content);

// Size of a record's opcode and length prefix.
inline constexpr uint64_t kRecordPrefix = 9;
// A footer record with its trailing magic: the fixed tail of every complete file.
inline constexpr uint64_t kFooterRecordSize = kRecordPrefix + 8 + 8 + 4;

}  // namespace autonomy::mcap
