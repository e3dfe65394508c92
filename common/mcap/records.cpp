#include "common/mcap/records.hpp"

#include <cstring>

namespace autonomy::mcap {

namespace {

template <typename T>
void put(std::string& out, T v) {
  unsigned char b[sizeof(T)];
  for (size_t i = 0; i < sizeof(T); ++i) b[i] = static_cast<unsigned char>((static_cast<uint64_t>(v) >> (8 * i)) & 0xFFu);
  out.append(reinterpret_cast<const char*>(b), sizeof(T));
}

void put_string(std::string& out, std::string_view s) {
  put<uint32_t>(out, static_cast<uint32_t>(s.size()));
  out.append(s);
}

void put_map(std::string& out, const std::map<std::string, std::string>& m) {
  std::string body;
  for (const auto& [k, v] : m) {
    put_string(body, k);
    put_string(body, v);
  }
  put_string(out, body);
}

template <typename V>
void put_id_map(std::string& out, const std::map<uint16_t, V>& m) {
  put<uint32_t>(out, static_cast<uint32_t>(m.size() * (2 + sizeof(V))));
  for (const auto& [k, v] : m) {
    put<uint16_t>(out, k);
    put<V>(out, v);
  }
}

// Writes the opcode and a length placeholder; finish() fills the length in.
size_t begin(std::string& out, Op op) {
  out.push_back(static_cast<char>(op));
  put<uint64_t>(out, 0);
  return out.size();
}

void finish(std::string& out, size_t content_start) {
  const uint64_t len = out.size() - content_start;
  for (size_t i = 0; i < 8; ++i) out[content_start - 8 + i] = static_cast<char>((len >> (8 * i)) & 0xFFu);
}

// Bounds-checked little-endian reading of one record's content.
class Cursor {
 public:
  Cursor(std::string_view content, const char* record) : s_(content), record_(record) {}

  template <typename T>
  T get(const char* field) {
    need(sizeof(T), field);
    uint64_t v = 0;
    for (size_t i = 0; i < sizeof(T); ++i) v |= static_cast<uint64_t>(static_cast<unsigned char>(s_[pos_ + i])) << (8 * i);
    pos_ += sizeof(T);
    return static_cast<T>(v);
  }
  std::string_view bytes(uint64_t n, const char* field) {
    need(n, field);
    auto v = s_.substr(pos_, n);
    pos_ += n;
    return v;
  }
  std::string string(const char* field) { return std::string(bytes(get<uint32_t>(field), field)); }
  std::string_view rest() {
    auto v = s_.substr(pos_);
    pos_ = s_.size();
    return v;
  }
  bool done() const { return pos_ >= s_.size(); }

 private:
  void need(uint64_t n, const char* field) const {
    if (n > s_.size() - pos_)
      throw McapError(std::string(record_) + " record: field " + field + " needs " + std::to_string(n) +
                      " bytes at content offset " + std::to_string(pos_) + ", only " +
                      std::to_string(s_.size() - pos_) + " left");
  }
  std::string_view s_;
  const char* record_;
  size_t pos_ = 0;
};

template <typename V>
std::map<uint16_t, V> get_id_map(Cursor& c, const char* field, const char* record) {
  Cursor m(c.bytes(c.get<uint32_t>(field), field), record);
  std::map<uint16_t, V> out;
  while (!m.done()) {
    const auto k = m.get<uint16_t>(field);
    out[k] = m.get<V>(field);
  }
  return out;
}

}  // namespace

const char* to_string(Op op) {
  switch (op) {
    case Op::Header: return "Header";
    case Op::Footer: return "Footer";
    case Op::Schema: return "Schema";
    case Op::Channel: return "Channel";
    case Op::Message: return "Message";
    case Op::Chunk: return "Chunk";
    case Op::MessageIndex: return "MessageIndex";
    case Op::ChunkIndex: return "ChunkIndex";
    case Op::Attachment: return "Attachment";
    case Op::AttachmentIndex: return "AttachmentIndex";
    case Op::Statistics: return "Statistics";
    case Op::Metadata: return "Metadata";
    case Op::MetadataIndex: return "MetadataIndex";
    case Op::SummaryOffset: return "SummaryOffset";
    case Op::DataEnd: return "DataEnd";
  }
  return "unknown";
}

void append(std::string& out, const Header& r) {
  const auto s = begin(out, Op::Header);
  put_string(out, r.profile);
  put_string(out, r.library);
  finish(out, s);
}

void append(std::string& out, const Footer& r) {
  const auto s = begin(out, Op::Footer);
  put<uint64_t>(out, r.summary_start);
  put<uint64_t>(out, r.summary_offset_start);
  put<uint32_t>(out, r.summary_crc);
  finish(out, s);
}

void append(std::string& out, const Schema& r) {
  const auto s = begin(out, Op::Schema);
  put<uint16_t>(out, r.id);
  put_string(out, r.name);
  put_string(out, r.encoding);
  put_string(out, r.data);
  finish(out, s);
}

void append(std::string& out, const Channel& r) {
  const auto s = begin(out, Op::Channel);
  put<uint16_t>(out, r.id);
  put<uint16_t>(out, r.schema_id);
  put_string(out, r.topic);
  put_string(out, r.message_encoding);
  put_map(out, r.metadata);
  finish(out, s);
}

void append(std::string& out, const Message& r) {
  const auto s = begin(out, Op::Message);
  put<uint16_t>(out, r.channel_id);
  put<uint32_t>(out, r.sequence);
  put<uint64_t>(out, r.log_time);
  put<uint64_t>(out, r.publish_time);
  out.append(r.data);
  finish(out, s);
}

void append(std::string& out, const Chunk& r) {
  const auto s = begin(out, Op::Chunk);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  put<uint64_t>(out, r.uncompressed_size);
  put<uint32_t>(out, r.uncompressed_crc);
  put_string(out, r.compression);
  put<uint64_t>(out, r.records.size());
  out.append(r.records);
  finish(out, s);
}

void append(std::string& out, const MessageIndex& r) {
  const auto s = begin(out, Op::MessageIndex);
  put<uint16_t>(out, r.channel_id);
  put<uint32_t>(out, static_cast<uint32_t>(r.records.size() * 16));
  for (const auto& [t, off] : r.records) {
    put<uint64_t>(out, t);
    put<uint64_t>(out, off);
  }
  finish(out, s);
}

void append(std::string& out, const ChunkIndex& r) {
  const auto s = begin(out, Op::ChunkIndex);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  put<uint64_t>(out, r.chunk_start_offset);
  put<uint64_t>(out, r.chunk_length);
  put_id_map(out, r.message_index_offsets);
  put<uint64_t>(out, r.message_index_length);
  put_string(out, r.compression);
  put<uint64_t>(out, r.compressed_size);
  put<uint64_t>(out, r.uncompressed_size);
  finish(out, s);
}

void append(std::string& out, const Statistics& r) {
  const auto s = begin(out, Op::Statistics);
  put<uint64_t>(out, r.message_count);
  put<uint16_t>(out, r.schema_count);
  put<uint32_t>(out, r.channel_count);
  put<uint32_t>(out, r.attachment_count);
  put<uint32_t>(out, r.metadata_count);
  put<uint32_t>(out, r.chunk_count);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  put_id_map(out, r.channel_message_counts);
  finish(out, s);
}

void append(std::string& out, const SummaryOffset& r) {
  const auto s = begin(out, Op::SummaryOffset);
  put<uint8_t>(out, static_cast<uint8_t>(r.group_opcode));
  put<uint64_t>(out, r.group_start);
  put<uint64_t>(out, r.group_length);
  finish(out, s);
}

void append(std::string& out, const DataEnd& r) {
  const auto s = begin(out, Op::DataEnd);
  put<uint32_t>(out, r.data_section_crc);
  finish(out, s);
}

Header parse_header(std::string_view content) {
  Cursor c(content, "Header");
  Header r;
  r.profile = c.string("profile");
  r.library = c.string("library");
  return r;
}

Footer parse_footer(std::string_view content) {
  Cursor c(content, "Footer");
  Footer r;
  r.summary_start = c.get<uint64_t>("summary_start");
  r.summary_offset_start = c.get<uint64_t>("summary_offset_start");
  r.summary_crc = c.get<uint32_t>("summary_crc");
  return r;
}

Schema parse_schema(std::string_view content) {
  Cursor c(content, "Schema");
  Schema r;
  r.id = c.get<uint16_t>("id");
  r.name = c.string("name");
  r.encoding = c.string("encoding");
  r.data = c.string("data");
  return r;
}

Channel parse_channel(std::string_view content) {
  Cursor c(content, "Channel");
  Channel r;
  r.id = c.get<uint16_t>("id");
  r.schema_id = c.get<uint16_t>("schema_id");
  r.topic = c.string("topic");
  r.message_encoding = c.string("message_encoding");
  Cursor m(c.bytes(c.get<uint32_t>("metadata"), "metadata"), "Channel");
  while (!m.done()) {
    auto k = m.string("metadata key");
    r.metadata[k] = m.string("metadata value");
  }
  return r;
}

Message parse_message(std::string_view content) {
  Cursor c(content, "Message");
  Message r;
  r.channel_id = c.get<uint16_t>("channel_id");
  r.sequence = c.get<uint32_t>("sequence");
  r.log_time = c.get<uint64_t>("log_time");
  r.publish_time = c.get<uint64_t>("publish_time");
  r.data = std::string(c.rest());
  return r;
}

Chunk parse_chunk(std::string_view content) {
  Cursor c(content, "Chunk");
  Chunk r;
  r.message_start_time = c.get<uint64_t>("message_start_time");
  r.message_end_time = c.get<uint64_t>("message_end_time");
  r.uncompressed_size = c.get<uint64_t>("uncompressed_size");
  r.uncompressed_crc = c.get<uint32_t>("uncompressed_crc");
  r.compression = c.string("compression");
  r.records = std::string(c.bytes(c.get<uint64_t>("records"), "records"));
  return r;
}

MessageIndex parse_message_index(std::string_view content) {
  Cursor c(content, "MessageIndex");
  MessageIndex r;
  r.channel_id = c.get<uint16_t>("channel_id");
  Cursor a(c.bytes(c.get<uint32_t>("records"), "records"), "MessageIndex");
  while (!a.done()) {
    const auto t = a.get<uint64_t>("records log_time");
    r.records.emplace_back(t, a.get<uint64_t>("records offset"));
  }
  return r;
}

ChunkIndex parse_chunk_index(std::string_view content) {
  Cursor c(content, "ChunkIndex");
  ChunkIndex r;
  r.message_start_time = c.get<uint64_t>("message_start_time");
  r.message_end_time = c.get<uint64_t>("message_end_time");
  r.chunk_start_offset = c.get<uint64_t>("chunk_start_offset");
  r.chunk_length = c.get<uint64_t>("chunk_length");
  r.message_index_offsets = get_id_map<uint64_t>(c, "message_index_offsets", "ChunkIndex");
  r.message_index_length = c.get<uint64_t>("message_index_length");
  r.compression = c.string("compression");
  r.compressed_size = c.get<uint64_t>("compressed_size");
  r.uncompressed_size = c.get<uint64_t>("uncompressed_size");
  return r;
}

Statistics parse_statistics(std::string_view content) {
  Cursor c(content, "Statistics");
  Statistics r;
  r.message_count = c.get<uint64_t>("message_count");
  r.schema_count = c.get<uint16_t>("schema_count");
  r.channel_count = c.get<uint32_t>("channel_count");
  r.attachment_count = c.get<uint32_t>("attachment_count");
  r.metadata_count = c.get<uint32_t>("metadata_count");
  r.chunk_count = c.get<uint32_t>("chunk_count");
  r.message_start_time = c.get<uint64_t>("message_start_time");
  r.message_end_time = c.get<uint64_t>("message_end_time");
  r.channel_message_counts = get_id_map<uint64_t>(c, "channel_message_counts", "Statistics");
  return r;
}

SummaryOffset parse_summary_offset(std::string_view content) {
  Cursor c(content, "SummaryOffset");
  SummaryOffset r;
  r.group_opcode = static_cast<Op>(c.get<uint8_t>("group_opcode"));
  r.group_start = c.get<uint64_t>("group_start");
  r.group_length = c.get<uint64_t>("group_length");
  return r;
}

DataEnd parse_data_end(std::string_view content) {
  Cursor c(content, "DataEnd");
  DataEnd r;
  r.data_section_crc = c.get<uint32_t>("data_section_crc");
  return r;
}

}  // namespace autonomy::mcap
