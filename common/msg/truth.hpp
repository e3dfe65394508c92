#pragma once
// C++ value types of idl/truth.idl: ground truth no robot senses directly.
#include <cstdint>
#include <string>

namespace autonomy::msg {

struct DoorState {
  std::string door_id;
  int64_t tick = 0;
  double angle = 0.0;
  double target_angle = 0.0;
  bool closed = false;
  bool blocked = false;
};

}  // namespace autonomy::msg
