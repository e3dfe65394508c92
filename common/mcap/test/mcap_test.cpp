// The MCAP writer and reader: round trips, the CRCs (chunk, data section, summary) and files cut
// short the way a killed writer leaves them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include "common/mcap/crc32.hpp"
#include "common/mcap/reader.hpp"
#include "common/mcap/writer.hpp"

namespace autonomy::mcap {
namespace {

namespace fs = std::filesystem;

class McapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mcap_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

struct Seen {
  std::string topic, schema_name, schema_encoding;
  Message message;
};

std::vector<Seen> read_all(const std::string& path, ReadReport* report = nullptr) {
  std::vector<Seen> out;
  Reader reader(path);
  auto r = reader.read([&](const Channel& c, const Schema* s, const Message& m) {
    out.push_back({c.topic, s ? s->name : "", s ? s->encoding : "", m});
  });
  if (report) *report = r;
  return out;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// 300 messages on three channels (two schemas), payloads of varying size; chunks of about 2 KiB.
std::vector<Message> write_sample(const std::string& path, const std::string& compression) {
  WriterOptions o;
  o.compression = compression;
  o.chunk_size = 2048;
  Writer w(path, o);
  const auto s1 = w.add_schema("autonomy::A", "omgidl", "module autonomy { struct A { long x; }; };");
  const auto s2 = w.add_schema("autonomy::B", "omgidl", "module autonomy { struct B { string s; }; };");
  const uint16_t ch[3] = {w.add_channel(s1, "a/one", "cdr", {{"reliability", "reliable"}}),
                          w.add_channel(s2, "b/two", "cdr", {}), w.add_channel(s1, "a/three", "cdr", {{"k", "v"}})};
  std::vector<Message> written;
  for (uint32_t i = 0; i < 300; ++i) {
    Message m;
    m.channel_id = ch[i % 3];
    m.sequence = i / 3;
    m.log_time = 1'000'000'000ull + i * 1000;
    m.publish_time = m.log_time - 7;
    m.data = std::string(4 + (i * 37) % 90, static_cast<char>('a' + i % 26));
    m.data[0] = static_cast<char>(i & 0xFF);
    w.write(m);
    written.push_back(m);
  }
  w.close();
  return written;
}

TEST(Crc32, MatchesTheZlibCheckValue) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);
  Crc32 split;
  split.update("1234");
  split.update("56789");
  EXPECT_EQ(split.value(), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST_F(McapTest, RoundTripKeepsEveryMessageInOrderWithChannelsAndSchemas) {
  for (const std::string compression : {"zstd", ""}) {
    const auto file = path("round" + compression + ".mcap");
    const auto written = write_sample(file, compression);
    ReadReport report;
    const auto seen = read_all(file, &report);
    ASSERT_EQ(seen.size(), written.size()) << compression;
    for (size_t i = 0; i < seen.size(); ++i) {
      EXPECT_EQ(seen[i].message.channel_id, written[i].channel_id);
      EXPECT_EQ(seen[i].message.sequence, written[i].sequence);
      EXPECT_EQ(seen[i].message.log_time, written[i].log_time);
      EXPECT_EQ(seen[i].message.publish_time, written[i].publish_time);
      EXPECT_EQ(seen[i].message.data, written[i].data);
      EXPECT_EQ(seen[i].schema_encoding, "omgidl");
    }
    EXPECT_EQ(seen[1].topic, "b/two");
    EXPECT_EQ(seen[1].schema_name, "autonomy::B");
    EXPECT_EQ(seen[2].schema_name, "autonomy::A");
    EXPECT_TRUE(report.complete);
    EXPECT_FALSE(report.truncated);
    EXPECT_TRUE(report.data_crc_checked);
    EXPECT_TRUE(report.summary_crc_checked);
    EXPECT_GT(report.chunks, 5u);  // 2 KiB chunks
    EXPECT_EQ(report.compressions, std::set<std::string>{compression});
    ASSERT_TRUE(report.summary_statistics.has_value());
    EXPECT_EQ(report.summary_statistics->message_count, 300u);
    EXPECT_EQ(report.summary_statistics->channel_count, 3u);
    EXPECT_EQ(report.summary_statistics->schema_count, 2);
    EXPECT_EQ(report.summary_statistics->channel_message_counts.at(1), 100u);
    EXPECT_EQ(report.summary_statistics->message_start_time, 1'000'000'000ull);
    EXPECT_EQ(report.summary_statistics->message_end_time, 1'000'000'000ull + 299 * 1000);
    EXPECT_EQ(report.summary_chunk_indexes, report.chunks);

    Reader again(file);
    again.read(nullptr);
    EXPECT_EQ(again.channels().at(0).metadata.at("reliability"), "reliable");
    EXPECT_EQ(again.channels().at(2).metadata.at("k"), "v");
  }
}

TEST_F(McapTest, ZstdChunksAreSmallerThanTheirRecords) {
  const auto file = path("z.mcap");
  write_sample(file, "zstd");
  ReadReport report;
  read_all(file, &report);
  EXPECT_LT(report.chunk_compressed_bytes * 2, report.chunk_uncompressed_bytes);
}

TEST_F(McapTest, FileStartsAndEndsWithMagicAndHeader) {
  const auto file = path("m.mcap");
  write_sample(file, "zstd");
  const auto b = bytes_of(file);
  EXPECT_EQ(b.substr(0, 8), std::string(kMagic));
  EXPECT_EQ(b.substr(b.size() - 8), std::string(kMagic));
  EXPECT_EQ(static_cast<Op>(b[8]), Op::Header);
  EXPECT_EQ(static_cast<Op>(b[b.size() - 8 - kFooterRecordSize]), Op::Footer);
  Reader r(file);
  EXPECT_EQ(r.header().library, "autonomy-mcap");
}

TEST_F(McapTest, AChangedByteInAChunkIsCaughtByItsCrc) {
  const auto file = path("c.mcap");
  write_sample(file, "");  // uncompressed: the changed byte reaches the chunk CRC, not the decompressor
  auto b = bytes_of(file);
  const auto at = b.find(std::string(20, 'k'));  // inside a message payload of the data section
  ASSERT_NE(at, std::string::npos);
  b[at] = 'K';
  write_bytes(file, b);
  try {
    read_all(file);
    FAIL() << "a corrupted chunk was read";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("chunk CRC"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
}

TEST_F(McapTest, AChangedDataEndCrcAndAChangedSummaryAreCaught) {
  const auto file = path("d.mcap");
  write_sample(file, "zstd");
  const auto good = bytes_of(file);
  // The summary starts after the data end record (opcode 0x0F, length 4, CRC).
  const auto footer_at = good.size() - 8 - kFooterRecordSize;
  uint64_t summary_start = 0;
  for (int i = 0; i < 8; ++i) summary_start |= static_cast<uint64_t>(static_cast<unsigned char>(good[footer_at + 9 + i])) << (8 * i);
  const auto data_end_at = summary_start - (kRecordPrefix + 4);
  ASSERT_EQ(static_cast<Op>(good[data_end_at]), Op::DataEnd);

  auto bad = good;
  bad[data_end_at + kRecordPrefix] ^= 0x01;
  write_bytes(file, bad);
  EXPECT_THROW(read_all(file), McapError);

  bad = good;
  bad[summary_start + kRecordPrefix + 4] ^= 0x01;  // inside the first summary record
  write_bytes(file, bad);
  try {
    read_all(file);
    FAIL() << "a corrupted summary was read";
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("summary CRC"), std::string::npos) << e.what();
  }
}

TEST_F(McapTest, ATruncatedFileIsReadUpToItsLastCompleteChunk) {
  const auto file = path("t.mcap");
  const auto written = write_sample(file, "zstd");
  const auto full = bytes_of(file);
  // Where each chunk ends: read the file record by record.
  std::vector<uint64_t> chunk_starts;
  uint64_t p = 8;
  while (p + kRecordPrefix <= full.size()) {
    const auto op = static_cast<Op>(full[p]);
    uint64_t len = 0;
    for (int i = 0; i < 8; ++i) len |= static_cast<uint64_t>(static_cast<unsigned char>(full[p + 1 + i])) << (8 * i);
    if (op == Op::Chunk) chunk_starts.push_back(p);
    if (op == Op::DataEnd) break;
    p += kRecordPrefix + len;
  }
  ASSERT_GE(chunk_starts.size(), 4u);

  // Count the messages of the first three chunks: cut inside the fourth.
  const auto cut = chunk_starts[3] + 40;
  write_bytes(path("cut.mcap"), full.substr(0, chunk_starts[3]));
  const auto three = read_all(path("cut.mcap")).size();
  ASSERT_GT(three, 0u);

  write_bytes(file, full.substr(0, cut));
  ReadReport report;
  const auto seen = read_all(file, &report);
  EXPECT_TRUE(report.truncated);
  EXPECT_FALSE(report.complete);
  EXPECT_EQ(report.chunks, 3u);
  EXPECT_EQ(report.readable_until, chunk_starts[3]);
  EXPECT_NE(report.note.find("inside a Chunk record"), std::string::npos) << report.note;
  ASSERT_EQ(seen.size(), three);
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i].message.data, written[i].data);

  // Cut inside a record header, and right after the header record: nothing lost, nothing invented.
  write_bytes(file, full.substr(0, chunk_starts[3] + 3));
  EXPECT_EQ(read_all(file, &report).size(), three);
  EXPECT_TRUE(report.truncated);
  write_bytes(file, full.substr(0, chunk_starts[0]));
  EXPECT_EQ(read_all(file, &report).size(), 0u);
  EXPECT_TRUE(report.truncated);
}

TEST_F(McapTest, NotAnMcapFileIsRefusedWithItsPath) {
  const auto file = path("x.txt");
  write_bytes(file, "hello, this is not a recording");
  try {
    Reader r(file);
    FAIL();
  } catch (const McapError& e) {
    EXPECT_NE(std::string(e.what()).find("not an MCAP file"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos);
  }
  EXPECT_THROW(Writer(path("no/such/dir/f.mcap")), McapError);
  EXPECT_THROW(Writer(path("f.mcap"), WriterOptions{"", "x", "lz5", 3, 1024}), McapError);
}

TEST_F(McapTest, AWriterDestroyedWithoutCloseStillLeavesACompleteFile) {
  const auto file = path("w.mcap");
  {
    Writer w(file);
    const auto s = w.add_schema("S", "omgidl", "x");
    const auto c = w.add_channel(s, "t", "cdr", {});
    w.write(Message{c, 0, 5, 5, "abc"});
  }
  ReadReport report;
  const auto seen = read_all(file, &report);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].message.data, "abc");
  EXPECT_TRUE(report.complete);
}

}  // namespace
}  // namespace autonomy::mcap
