#include "services/courier/core/execution/job.hpp"

namespace autonomy::courier {

const char* to_string(JobState s) {
  switch (s) {
    case JobState::queued: return "queued";
    case JobState::underway: return "underway";
    case JobState::opportunistic: return "opportunistic";
    case JobState::completed: return "completed";
    case JobState::failed: return "failed";
    case JobState::cancelled: return "cancelled";
    case JobState::stranded: return "stranded";
  }
  return "?";
}

const char* to_string(JobPhase p) {
  switch (p) {
    case JobPhase::none: return "";
    case JobPhase::to_pickup: return "to_pickup";
    case JobPhase::loading: return "loading";
    case JobPhase::to_destination: return "to_destination";
    case JobPhase::unloading: return "unloading";
    case JobPhase::returning: return "returning";
  }
  return "?";
}

std::optional<JobState> job_state_from(const std::string& word) {
  for (const JobState s : {JobState::queued, JobState::underway, JobState::opportunistic, JobState::completed,
                           JobState::failed, JobState::cancelled, JobState::stranded})
    if (word == to_string(s)) return s;
  return std::nullopt;
}

NextStep next_step(const Job& job) {
  if (job.finished()) return NextStep::none;
  if (job.aboard()) return NextStep::unload;
  if (job.object_place == job.target_place()) return NextStep::none;
  // Lying anywhere else: it has to be fetched first. A returned object is fetched from where it
  // lies, which is the pickup unless a handover left it elsewhere.
  return NextStep::load;
}

}  // namespace autonomy::courier
