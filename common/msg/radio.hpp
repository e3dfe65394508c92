#pragma once
// C++ value types of idl/radio.idl: links, team connectivity and relayed team messages.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct RadioLink {
  std::string robot_a;  // robot_a < robot_b
  std::string robot_b;
  int64_t tick = 0;
  double signal_dbm = 0.0;
  double margin_db = 0.0;
  bool connected = false;
};

struct TeamComponent {
  std::vector<std::string> robots;
};

struct TeamConnectivity {
  int64_t tick = 0;
  std::vector<TeamComponent> components;
  bool fully_connected = true;
};

// "to" of a broadcast.
inline constexpr const char* kBroadcast = "*";

struct TeamMessage {
  std::string from;
  std::string to;
  std::string message_id;
  std::string payload;
};

struct TeamDelivery {
  std::string recipient;
  std::string from;
  std::string to;
  std::string message_id;
  std::string payload;
  int64_t sent_time_ns = 0;
  int64_t delivered_time_ns = 0;
  uint32_t hops = 0;
};

}  // namespace autonomy::msg
