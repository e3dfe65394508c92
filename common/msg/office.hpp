#pragma once
// C++ value types of idl/office.idl: load/unload requests and their answers, object ground truth.
#include <cstdint>
#include <string>

namespace autonomy::msg {

enum class HandoverKind { Load, Unload };
enum class HandoverState { Accepted, Rejected, Completed, Failed };

struct HandoverRequest {
  std::string request_id;
  std::string requester;
  std::string robot_id;
  HandoverKind kind = HandoverKind::Load;
  std::string place;
  std::string object_id;
};

struct HandoverStatus {
  std::string request_id;
  std::string robot_id;
  HandoverKind kind = HandoverKind::Load;
  std::string place;
  std::string object_id;
  HandoverState state = HandoverState::Rejected;
  std::string reason;
  std::string detail;
  std::string helper;
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  int64_t completes_at_ns = 0;
};

struct ObjectState {
  std::string object_id;
  std::string kind;
  std::string colour;
  std::string place;
  std::string carrier;
  int64_t tick = 0;
};

const char* to_string(HandoverKind k);
const char* to_string(HandoverState s);

}  // namespace autonomy::msg
