#pragma once
// Sizes and times for people: "12.3 KiB", "4.250 s", "2026-12-03 19:00:00.123 UTC".
#include <cstdint>
#include <string>

namespace autonomy::tools {

std::string human_bytes(uint64_t bytes);
std::string utc_time(uint64_t ns_since_epoch);

}  // namespace autonomy::tools

namespace autonomy::tools {

// For "nothing seen" messages: which domain and DDS profile this process used, and how to set
// them to match the processes one expected to see.
std::string where_we_looked(int domain);

}  // namespace autonomy::tools
