#pragma once
// The rule for robot ids, shared by spawning and scenario checking. Ids become DDS keys, log
// fields and file names, so they are restricted to a portable character set.
#include <optional>
#include <string>

namespace autonomy::sim {

inline constexpr std::size_t kMaxRobotIdLength = 64;

// Why `id` is not a valid robot id, or nothing when it is. Valid: 1..64 characters from
// [A-Za-z0-9_.-].
std::optional<std::string> robot_id_problem(const std::string& id);

}  // namespace autonomy::sim
