// autonomy bag info: what an MCAP recording holds (docs/recording.md).
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "common/mcap/reader.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/text.hpp"

namespace autonomy::tools {

namespace {

struct PerChannel {
  uint64_t messages = 0, bytes = 0;
};

std::string qos_of(const mcap::Channel& c) {
  auto get = [&](const char* k) {
    const auto it = c.metadata.find(k);
    return it == c.metadata.end() ? std::string("?") : it->second;
  };
  if (c.metadata.empty()) return "-";
  std::string s = get("reliability") + " " + get("durability") + " " + get("history");
  if (get("history") == "keep-last") s += " " + get("depth");
  return s;
}

int run_bag_info(const std::string& path) {
  mcap::Reader reader(path);
  std::map<uint16_t, PerChannel> per;
  uint64_t first = 0, last = 0, count = 0;
  const auto report = reader.read([&](const mcap::Channel& c, const mcap::Schema*, const mcap::Message& m) {
    auto& p = per[c.id];
    ++p.messages;
    p.bytes += m.data.size();
    if (count++ == 0) first = last = m.log_time;
    first = std::min(first, m.log_time);
    last = std::max(last, m.log_time);
  });
  std::ostringstream o;
  o << "path:         " << path << "\n";
  o << "size:         " << human_bytes(report.file_size) << "\n";
  o << "written by:   " << (reader.header().library.empty() ? "?" : reader.header().library) << "\n";
  if (report.complete) {
    o << "state:        complete (data CRC " << (report.data_crc_checked ? "ok" : "absent") << ", summary CRC "
      << (report.summary_crc_checked ? "ok" : "absent") << ", chunk CRCs ok)\n";
  } else {
    o << "state:        INCOMPLETE: " << report.note << "; read up to byte " << report.readable_until << "\n";
  }
  if (count > 0) {
    o << "duration:     " << std::fixed << std::setprecision(3) << (last - first) / 1e9 << " s\n";
    o << "start:        " << utc_time(first) << "\n";
    o << "end:          " << utc_time(last) << "\n";
  }
  o << "messages:     " << count << "\n";
  std::string compressions;
  for (const auto& c : report.compressions) compressions += (compressions.empty() ? "" : ", ") + (c.empty() ? std::string("none") : c);
  o << "chunks:       " << report.chunks << " (" << (compressions.empty() ? "none" : compressions) << "; "
    << human_bytes(report.chunk_compressed_bytes) << " stored for " << human_bytes(report.chunk_uncompressed_bytes);
  if (report.chunk_uncompressed_bytes > 0)
    o << ", " << std::setprecision(0) << 100.0 * report.chunk_compressed_bytes / report.chunk_uncompressed_bytes << " %";
  o << ")\n";
  o << "topics:       " << reader.channels().size() << "\n";
  size_t wt = 5, wy = 4;
  for (const auto& [id, c] : reader.channels()) {
    wt = std::max(wt, c.topic.size());
    const auto s = reader.schemas().find(c.schema_id);
    if (s != reader.schemas().end()) wy = std::max(wy, s->second.name.size());
  }
  o << "  " << std::left << std::setw(static_cast<int>(wt)) << "topic" << "  " << std::setw(static_cast<int>(wy)) << "type"
    << std::right << std::setw(9) << "msgs" << std::setw(12) << "bytes" << "  qos\n";
  for (const auto& [id, c] : reader.channels()) {
    const auto s = reader.schemas().find(c.schema_id);
    const auto& p = per[id];
    o << "  " << std::left << std::setw(static_cast<int>(wt)) << c.topic << "  " << std::setw(static_cast<int>(wy))
      << (s == reader.schemas().end() ? std::string("-") : s->second.name) << std::right << std::setw(9) << p.messages
      << std::setw(12) << human_bytes(p.bytes) << "  " << qos_of(c) << "\n";
  }
  std::cout << o.str() << std::flush;
  return kExitOk;
}

}  // namespace

Command add_bag_info(CLI::App& bag) {
  auto path = std::make_shared<std::string>();
  auto* cmd = bag.add_subcommand("info",
                                 "Summarise an MCAP recording: duration, topics, types, counts, sizes, compression, "
                                 "and whether it is complete (every CRC checked) or was cut short");
  cmd->add_option("file", *path, "MCAP file")->required()->check(CLI::ExistingFile);
  return {cmd, [path](Context&) {
            try {
              return run_bag_info(*path);
            } catch (const mcap::McapError& e) {
              std::cerr << "autonomy bag info: " << e.what() << "\n";
              return static_cast<int>(kExitFailed);
            }
          }};
}

}  // namespace autonomy::tools
