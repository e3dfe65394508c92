#include "common/mcap/writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "common/mcap/compression.hpp"

namespace autonomy::mcap {

Writer::Writer(const std::string& path, WriterOptions options) : path_(path), options_(std::move(options)) {
  if (!compression_supported(options_.compression))
    throw McapError(path_ + ": compression \"" + options_.compression + "\" is not supported (use zstd or none)");
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) throw McapError(path_ + ": cannot create: " + std::strerror(errno));
  std::string head(kMagic);
  append(head, Header{options_.profile, options_.library});
  write_out(head, true);
}

Writer::~Writer() {
  try {
    close();
  } catch (...) {
    // A destructor must not throw; close() reported nothing because nobody called it.
  }
  if (fd_ >= 0) ::close(fd_);
}

uint16_t Writer::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  Schema s{static_cast<uint16_t>(schemas_.size() + 1), name, encoding, data};
  append(chunk_records_, s);
  schemas_.push_back(s);
  stats_.schema_count = static_cast<uint16_t>(schemas_.size());
  return s.id;
}

uint16_t Writer::add_channel(uint16_t schema_id, const std::string& topic, const std::string& message_encoding,
                             const std::map<std::string, std::string>& metadata) {
  if (schema_id > schemas_.size())
    throw McapError(path_ + ": channel " + topic + " names schema " + std::to_string(schema_id) + ", which was not added");
  Channel c{static_cast<uint16_t>(channels_.size()), schema_id, topic, message_encoding, metadata};
  append(chunk_records_, c);
  channels_.push_back(c);
  stats_.channel_count = static_cast<uint32_t>(channels_.size());
  return c.id;
}

void Writer::write(const Message& m) {
  if (m.channel_id >= channels_.size())
    throw McapError(path_ + ": message on channel " + std::to_string(m.channel_id) + ", which was not added");
  auto& index = chunk_index_[m.channel_id];
  index.channel_id = m.channel_id;
  index.records.emplace_back(m.log_time, chunk_records_.size());
  append(chunk_records_, m);
  if (!chunk_has_messages_) {
    chunk_start_ = chunk_end_ = m.log_time;
    chunk_has_messages_ = true;
  }
  chunk_start_ = std::min(chunk_start_, m.log_time);
  chunk_end_ = std::max(chunk_end_, m.log_time);
  if (stats_.message_count == 0) stats_.message_start_time = stats_.message_end_time = m.log_time;
  stats_.message_start_time = std::min(stats_.message_start_time, m.log_time);
  stats_.message_end_time = std::max(stats_.message_end_time, m.log_time);
  ++stats_.message_count;
  ++stats_.channel_message_counts[m.channel_id];
  if (chunk_records_.size() >= options_.chunk_size) flush_chunk();
}

void Writer::flush_chunk() {
  if (fd_ < 0 || chunk_records_.empty()) return;
  Chunk chunk;
  chunk.message_start_time = chunk_has_messages_ ? chunk_start_ : 0;
  chunk.message_end_time = chunk_has_messages_ ? chunk_end_ : 0;
  chunk.uncompressed_size = chunk_records_.size();
  chunk.uncompressed_crc = crc32(chunk_records_);
  chunk.compression = options_.compression;
  chunk.records = compress(options_.compression, chunk_records_, options_.compression_level);

  ChunkIndex ci;
  ci.message_start_time = chunk.message_start_time;
  ci.message_end_time = chunk.message_end_time;
  ci.chunk_start_offset = offset_;
  ci.compression = chunk.compression;
  ci.compressed_size = chunk.records.size();
  ci.uncompressed_size = chunk.uncompressed_size;

  // The chunk and its message indexes go out in one write, so that a kill leaves either both
  // or a torn tail that the reader recognises as incomplete.
  std::string out;
  append(out, chunk);
  ci.chunk_length = out.size();
  for (auto& [id, index] : chunk_index_) {
    // Readers look messages up by time: the index is in log-time order (stable for equal times).
    std::stable_sort(index.records.begin(), index.records.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    ci.message_index_offsets[id] = offset_ + out.size();
    append(out, index);
  }
  ci.message_index_length = out.size() - ci.chunk_length;
  write_out(out, true);

  chunk_indexes_.push_back(std::move(ci));
  ++stats_.chunk_count;
  chunk_records_.clear();
  chunk_index_.clear();
  chunk_has_messages_ = false;
}

void Writer::close() {
  if (fd_ < 0) return;
  flush_chunk();
  std::string out;
  append(out, DataEnd{data_crc_.value()});
  write_out(out, false);

  // Summary: groups by opcode, each group's place in a summary offset record.
  const uint64_t summary_start = offset_;
  std::string summary;
  std::vector<SummaryOffset> offsets;
  auto group = [&](Op op, auto&& write_group) {
    const uint64_t start = summary.size();
    write_group();
    if (summary.size() > start) offsets.push_back({op, summary_start + start, summary.size() - start});
  };
  group(Op::Schema, [&] {
    for (const auto& s : schemas_) append(summary, s);
  });
  group(Op::Channel, [&] {
    for (const auto& c : channels_) append(summary, c);
  });
  group(Op::Statistics, [&] { append(summary, stats_); });
  group(Op::ChunkIndex, [&] {
    for (const auto& ci : chunk_indexes_) append(summary, ci);
  });
  const uint64_t summary_offset_start = summary_start + summary.size();
  for (const auto& o : offsets) append(summary, o);

  Footer footer{summary_start, summary_offset_start, 0};
  std::string footer_bytes;
  append(footer_bytes, footer);
  Crc32 summary_crc;
  summary_crc.update(summary);
  summary_crc.update(footer_bytes.data(), footer_bytes.size() - 4);  // up to, not including, the CRC itself
  footer.summary_crc = summary_crc.value();
  footer_bytes.clear();
  append(footer_bytes, footer);
  write_out(summary + footer_bytes + std::string(kMagic), false);

  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) throw McapError(path_ + ": close failed: " + std::strerror(errno));
}

void Writer::write_out(const std::string& bytes, bool data_section) {
  if (data_section) data_crc_.update(bytes);
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd_, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw McapError(path_ + ": write failed at byte " + std::to_string(offset_ + done) + ": " + std::strerror(errno));
    done += static_cast<size_t>(n);
  }
  offset_ += bytes.size();
}

}  // namespace autonomy::mcap
