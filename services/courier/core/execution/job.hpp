#pragma once
// A delivery job as the executive runs it. Where a job stands is derived from where its object is
// believed to be (at a place, or aboard a robot) and from the job's goal (deliver, or return the
// object after a cancel or a failure), never from a step counter: interrupting, rescheduling or
// restarting after a crash gives the same next step as running once.
#include <optional>
#include <string>

namespace autonomy::courier {

// stranded: its object is aboard a robot that left or was lost; the job waits for that robot to come
// back (it then goes on), and its reason says where the robot was last seen.
enum class JobState { queued, underway, opportunistic, completed, failed, cancelled, stranded };
enum class JobPhase { none, to_pickup, loading, to_destination, unloading, returning };

const char* to_string(JobState s);
const char* to_string(JobPhase p);
// Inverse of to_string (journal rows); nullopt for an unknown word.
std::optional<JobState> job_state_from(const std::string& word);

struct ObjectRef {
  std::string id;
  std::string kind;
  std::string colour;
  // Objects of one class (same kind and colour) look alike: never two aboard one robot at once.
  std::string lookalike_class() const { return kind + "/" + colour; }
};

struct Job {
  std::string id;
  std::string command_id;
  ObjectRef object;
  std::string pickup;       // place
  std::string destination;  // place
  std::optional<double> deadline_s;  // seconds of the day
  double accepted_at_s = 0.0;

  JobState state = JobState::queued;
  JobPhase phase = JobPhase::none;
  std::string robot;   // the courier robot assigned, or ""
  std::string reason;  // why it waits, failed or was cancelled
  std::optional<double> estimated_completion_s;
  // Why this robot (several couriers): "assigned to rhino2: 3 min earlier than rhino1"; from the
  // latest schedule, not journalled.
  std::string allocation;

  // Belief about the object: exactly one of the two is non-empty.
  std::string object_place;    // where it lies
  std::string object_carrier;  // the robot carrying it
  // Set when the object is to be brought back instead of delivered (cancelled or failed job).
  std::string return_to;
  JobState end_state_after_return = JobState::cancelled;
  std::string return_reason;  // why it is returned; the job's reason once the object is back

  std::string reason_after_return() const { return return_reason + "; " + object.id + " returned to " + return_to; }

  bool finished() const {
    return state == JobState::completed || state == JobState::failed || state == JobState::cancelled;
  }
  bool aboard() const { return !object_carrier.empty(); }
  // The place the object must go next: its destination, or return_to while returning.
  const std::string& target_place() const { return return_to.empty() ? destination : return_to; }
};

// What the job needs next, from its object belief: nothing (finished or the object where it
// should be), a load at the pickup, or an unload at the target place.
enum class NextStep { none, load, unload };
NextStep next_step(const Job& job);

}  // namespace autonomy::courier
