#pragma once
// C++ value types of idl/courier.idl: courier commands and replies, job states, schedules, reports.
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

enum class CourierCommandKind { Text, Deliver, Cancel, Revise };

struct CourierCommand {
  std::string command_id;
  std::string requester;
  CourierCommandKind kind = CourierCommandKind::Text;
  std::string text;
  std::string job_id;
  std::string object_id;
  std::string object_kind;
  std::string object_colour;
  std::string from;
  std::string to;
  std::string deadline;
};

struct CourierReply {
  std::string command_id;
  bool accepted = false;
  std::string job_id;
  std::string action;
  std::string object;
  std::string from;
  std::string to;
  std::string deadline;
  std::vector<std::string> assumptions;
  std::string reason;
  std::string detail;
  std::string word;
  int32_t column = 0;
  std::vector<std::string> suggestions;
  int64_t tick = 0;
};

enum class JobState { Queued, Underway, Opportunistic, Completed, Failed, Cancelled, Stranded };

struct CourierJobStatus {
  std::string job_id;
  std::string command_id;
  JobState state = JobState::Queued;
  std::string phase;
  std::string robot_id;
  std::string object_id;
  std::string object_kind;
  std::string object_colour;
  std::string from;
  std::string to;
  std::string deadline;
  std::string estimated_completion;
  std::string reason;
  std::string allocation;
  int64_t tick = 0;
};

struct CourierStop {
  std::string job_id;
  std::string action;
  std::string place;
  std::string room;
  double arrival_s = 0.0;
  double finish_s = 0.0;
};

struct CourierSchedule {
  std::string robot_id;
  std::string engine;
  bool proved_optimal = false;
  std::vector<CourierStop> stops;
  std::vector<std::string> assumptions;
  int32_t late_jobs = 0;
  double total_lateness_s = 0.0;
  int64_t tick = 0;
};

struct CourierReport {
  std::string command_id;
  std::string job_id;
  bool success = false;
  std::string text;
  int64_t tick = 0;
};

const char* to_string(CourierCommandKind k);
const char* to_string(JobState s);

}  // namespace autonomy::msg
