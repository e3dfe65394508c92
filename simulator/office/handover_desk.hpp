#pragma once
// The simulator's counter for load and unload requests: what the DDS node calls, so the node
// only converts samples. It checks a request as it arrives over the network (ids well formed,
// the robot in the world), hands it to OfficeState, remembers the answer under the request id
// (a requester repeats a request until it hears back; a repeat gets the latest answer again and
// never starts a second handover), turns OfficeState's outcomes back into answers to the
// requests they came from, and reports which objects moved since the ground truth was last
// published.
//
// Pure and deterministic like OfficeState: time and robot positions are passed in; the random
// generator is seeded once from the run's seed.
#include "common/geometry/geometry.hpp"
#include "simulator/office/office_state.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace autonomy::sim::office {

struct DeskRequest {
  std::string request_id;  // 1..128 characters; echoed in every answer
  std::string robot_id;
  HandoverKind kind = HandoverKind::load;
  std::string place;
  std::string object_id;
};

// What the world says about the requesting robot now; absent when it is not in the world.
struct RobotAtDesk {
  geometry::Vec2 position{0.0, 0.0};
  int capacity = 1;
};

enum class DeskAnswerState { accepted, rejected, completed, failed };
const char* to_string(DeskAnswerState state);

// Rejection reasons beyond HandoverRejection's (to_string of which are the other codes).
inline constexpr const char* kInvalidRequest = "invalid_request";  // malformed ids
inline constexpr const char* kUnknownRobot = "unknown_robot";      // not in the world
inline constexpr const char* kNoOffice = "no_office";  // the scenario has no office (used by the node)

struct DeskAnswer {
  std::string request_id;
  std::string robot_id;
  HandoverKind kind = HandoverKind::load;
  std::string place;
  std::string object_id;
  DeskAnswerState state = DeskAnswerState::rejected;
  std::string reason;  // rejected / failed: a code (to_string of the enum, or the constants above)
  std::string detail;  // one sentence, for every state
  std::string helper;  // accepted / completed / failed: the person's name or "station"
  double time_s = 0.0;            // simulated time of this answer (completion time when completed)
  double completes_at_s = 0.0;    // accepted / completed / failed: the planned completion time
};

// The answer to a request when the scenario has no office at all (reason kNoOffice).
DeskAnswer no_office_answer(const DeskRequest& request, double now_s);

class HandoverDesk {
 public:
  // Throws std::invalid_argument when spec has problems (see OfficeState).
  HandoverDesk(OfficeSpec spec, uint64_t seed);

  // Answers one request at simulated time now_s: accepted or rejected, or for a request id seen
  // before the latest answer to it (nothing new happens). `robot` is the requesting robot as the
  // world has it now.
  DeskAnswer request(const DeskRequest& request, const std::optional<RobotAtDesk>& robot, double now_s);

  // Moves the office to now_s (see OfficeState::advance) and answers the requests whose
  // handovers completed or failed, in OfficeState's order.
  std::vector<DeskAnswer> advance(double now_s, const std::map<std::string, geometry::Vec2>& robot_positions);

  // Objects whose location differs from the last call's (every object on the first call), in
  // declaration order.
  std::vector<ObjectItem> changed_objects();

  const OfficeState& office() const { return office_; }

 private:
  DeskAnswer answer(const DeskRequest& r, DeskAnswerState state, std::string reason, std::string detail,
                    double now_s);

  OfficeState office_;
  std::mt19937_64 rng_;
  std::map<std::string, DeskAnswer> answers_;       // request id -> latest answer
  std::map<uint64_t, std::string> request_of_;      // handover id -> request id
  std::map<std::string, ObjectLocation> published_;  // object id -> location last reported
};

}  // namespace autonomy::sim::office
