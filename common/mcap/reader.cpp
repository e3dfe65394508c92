#include "common/mcap/reader.hpp"

#include "common/mcap/compression.hpp"
#include "common/mcap/crc32.hpp"

namespace autonomy::mcap {

namespace {

uint64_t le64(const char* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<uint64_t>(static_cast<unsigned char>(p[i])) << (8 * i);
  return v;
}

}  // namespace

Reader::Reader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
  if (!in_) throw McapError(path_ + ": cannot open");
  in_.seekg(0, std::ios::end);
  size_ = static_cast<uint64_t>(in_.tellg());
  in_.seekg(0);
  std::string magic(kMagic.size(), '\0');
  if (!in_.read(magic.data(), static_cast<std::streamsize>(magic.size())) || magic != kMagic)
    throw McapError(path_ + ": not an MCAP file (no MCAP magic at its start)");
  char prefix[kRecordPrefix];
  if (!in_.read(prefix, kRecordPrefix) || static_cast<Op>(prefix[0]) != Op::Header)
    fail(kMagic.size(), "expected the Header record after the magic");
  const uint64_t len = le64(prefix + 1);
  if (len > size_ - kMagic.size() - kRecordPrefix) fail(kMagic.size(), "Header record runs past the end of the file");
  std::string content(len, '\0');
  in_.read(content.data(), static_cast<std::streamsize>(len));
  header_ = parse_header(content);
  header_end_ = kMagic.size() + kRecordPrefix + len;
}

void Reader::fail(uint64_t offset, const std::string& what) const {
  throw McapError(path_ + ": byte " + std::to_string(offset) + ": " + what);
}

ReadReport Reader::read(const OnMessage& on_message) {
  ReadReport report;
  report.file_size = size_;
  Crc32 data_crc;
  {
    std::string head(header_end_, '\0');
    in_.seekg(0);
    in_.read(head.data(), static_cast<std::streamsize>(head.size()));
    data_crc.update(head);
  }
  uint64_t pos = header_end_;
  report.readable_until = pos;
  std::string content;
  for (;;) {
    if (size_ - pos < kRecordPrefix) {
      report.truncated = true;
      report.note = "the file ends at byte " + std::to_string(size_) + " without a data end record" +
                    (pos == size_ ? "" : " (inside a record header)") + ": its writer did not close it";
      return report;
    }
    in_.seekg(static_cast<std::streamoff>(pos));
    char prefix[kRecordPrefix];
    in_.read(prefix, kRecordPrefix);
    const auto op = static_cast<Op>(prefix[0]);
    const uint64_t len = le64(prefix + 1);
    if (len > size_ - pos - kRecordPrefix) {
      report.truncated = true;
      report.note = "the file ends inside a " + std::string(to_string(op)) + " record at byte " + std::to_string(pos) +
                    " (" + std::to_string(size_ - pos - kRecordPrefix) + " of its " + std::to_string(len) +
                    " bytes present): its writer did not close it";
      return report;
    }
    content.assign(len, '\0');
    in_.read(content.data(), static_cast<std::streamsize>(len));
    if (op == Op::DataEnd) {
      const auto end = parse_data_end(content);
      if (end.data_section_crc != 0) {
        if (end.data_section_crc != data_crc.value())
          fail(pos, "data section CRC " + std::to_string(data_crc.value()) + " differs from the data end's " +
                        std::to_string(end.data_section_crc));
        report.data_crc_checked = true;
      }
      report.readable_until = pos + kRecordPrefix + len;
      summary(pos, report);
      return report;
    }
    data_crc.update(prefix, kRecordPrefix);
    data_crc.update(content);
    try {
      if (op == Op::Chunk) {
        const auto chunk = parse_chunk(content);
        const auto records_bytes = decompress(chunk.compression, chunk.records, chunk.uncompressed_size);
        if (chunk.uncompressed_crc != 0 && crc32(records_bytes) != chunk.uncompressed_crc)
          throw McapError("chunk CRC " + std::to_string(crc32(records_bytes)) + " differs from its header's " +
                          std::to_string(chunk.uncompressed_crc));
        ++report.chunks;
        report.chunk_compressed_bytes += chunk.records.size();
        report.chunk_uncompressed_bytes += chunk.uncompressed_size;
        report.compressions.insert(chunk.compression);
        records(records_bytes, 0, on_message, report);
      } else {
        std::string whole(prefix, kRecordPrefix);
        whole += content;
        records(whole, 0, on_message, report);
      }
    } catch (const McapError& e) {
      fail(pos, e.what());
    }
    pos += kRecordPrefix + len;
    report.readable_until = pos;
  }
}

// Schema, channel and message records (the content of a chunk, or one record of the data
// section); index records and records of other kinds are skipped.
void Reader::records(std::string_view bytes, uint64_t base, const OnMessage& on_message, ReadReport& report) {
  uint64_t p = 0;
  while (p < bytes.size()) {
    if (bytes.size() - p < kRecordPrefix) throw McapError("record header cut at offset " + std::to_string(base + p));
    const auto op = static_cast<Op>(bytes[p]);
    const uint64_t len = le64(bytes.data() + p + 1);
    if (len > bytes.size() - p - kRecordPrefix)
      throw McapError(std::string(to_string(op)) + " record at offset " + std::to_string(base + p) + " runs past its end");
    const auto content = bytes.substr(p + kRecordPrefix, len);
    switch (op) {
      case Op::Schema: {
        auto s = parse_schema(content);
        schemas_[s.id] = std::move(s);
        break;
      }
      case Op::Channel: {
        auto c = parse_channel(content);
        channels_[c.id] = std::move(c);
        break;
      }
      case Op::Message: {
        const auto m = parse_message(content);
        const auto c = channels_.find(m.channel_id);
        if (c == channels_.end())
          throw McapError("message at offset " + std::to_string(base + p) + " on channel " +
                          std::to_string(m.channel_id) + ", which no earlier channel record defines");
        const auto s = schemas_.find(c->second.schema_id);
        ++report.messages;
        if (on_message) on_message(c->second, s == schemas_.end() ? nullptr : &s->second, m);
        break;
      }
      default:
        break;
    }
    p += kRecordPrefix + len;
  }
}

void Reader::summary(uint64_t data_end_offset, ReadReport& report) {
  const uint64_t tail = kFooterRecordSize + kMagic.size();
  if (size_ < tail || size_ - tail < report.readable_until) fail(report.readable_until, "no footer after the data end");
  std::string rest(size_ - report.readable_until, '\0');
  in_.seekg(static_cast<std::streamoff>(report.readable_until));
  in_.read(rest.data(), static_cast<std::streamsize>(rest.size()));
  if (rest.substr(rest.size() - kMagic.size()) != kMagic) fail(size_ - kMagic.size(), "no MCAP magic at the end");
  const std::string_view footer_record(rest.data() + rest.size() - tail, kFooterRecordSize);
  if (static_cast<Op>(footer_record[0]) != Op::Footer) fail(size_ - tail, "expected the footer record");
  const auto footer = parse_footer(footer_record.substr(kRecordPrefix));
  if (footer.summary_start != 0) {
    if (footer.summary_start != report.readable_until)
      fail(size_ - tail, "footer's summary start " + std::to_string(footer.summary_start) +
                             " is not where the data end finishes (" + std::to_string(report.readable_until) + ")");
    if (footer.summary_crc != 0) {
      Crc32 crc;
      crc.update(rest.data(), rest.size() - tail);
      crc.update(footer_record.data(), kRecordPrefix + 16);
      if (crc.value() != footer.summary_crc)
        fail(footer.summary_start, "summary CRC " + std::to_string(crc.value()) + " differs from the footer's " +
                                       std::to_string(footer.summary_crc));
      report.summary_crc_checked = true;
    }
    std::string_view s(rest.data(), rest.size() - tail);
    uint64_t p = 0;
    while (p < s.size()) {
      const uint64_t at = footer.summary_start + p;
      if (s.size() - p < kRecordPrefix) fail(at, "summary record header cut");
      const auto op = static_cast<Op>(s[p]);
      const uint64_t len = le64(s.data() + p + 1);
      if (len > s.size() - p - kRecordPrefix) fail(at, std::string(to_string(op)) + " summary record runs past the footer");
      const auto content = s.substr(p + kRecordPrefix, len);
      try {
        if (op == Op::Statistics) report.summary_statistics = parse_statistics(content);
        if (op == Op::ChunkIndex) {
          const auto ci = parse_chunk_index(content);
          if (ci.chunk_start_offset >= data_end_offset) fail(at, "chunk index points past the data section");
          ++report.summary_chunk_indexes;
        }
        if (op == Op::SummaryOffset) {
          const auto so = parse_summary_offset(content);
          if (so.group_start < footer.summary_start || so.group_start + so.group_length > footer.summary_offset_start)
            fail(at, "summary offset group lies outside the summary section");
        }
      } catch (const McapError& e) {
        fail(at, e.what());
      }
      p += kRecordPrefix + len;
    }
    if (report.summary_statistics) {
      const auto& st = *report.summary_statistics;
      if (st.message_count != report.messages)
        fail(footer.summary_start, "summary statistics count " + std::to_string(st.message_count) +
                                       " messages, the data section holds " + std::to_string(report.messages));
      if (st.chunk_count != report.chunks || report.summary_chunk_indexes != report.chunks)
        fail(footer.summary_start, "summary statistics count " + std::to_string(st.chunk_count) + " chunks (" +
                                       std::to_string(report.summary_chunk_indexes) + " chunk indexes), the data section holds " +
                                       std::to_string(report.chunks));
    }
  }
  report.complete = true;
}

}  // namespace autonomy::mcap
