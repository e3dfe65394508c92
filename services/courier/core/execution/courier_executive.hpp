#pragma once
// The courier's plan executive (the paper's primary activities and policies), pure: events in
// (commands already accepted, poses, door sightings, goal and handover statuses, ticks), orders out
// (navigation goals, handover requests, job and schedule changes, top-level reports).
//
// Primary activities: per job, go to where the object lies, ask for the load, go to its
// destination, ask for the unload. Which step comes next is derived from the object belief (see
// job.hpp), so every activity can be interrupted and restarted.
// Policies: every door sighting is folded into the door belief; a door seen closed that an open
// step needs makes its job opportunistic ("A-120 closed at 10:14:05") and reschedules in the same
// tick; a door seen open that enables an opportunistic job triggers the opportunity check: the job
// is taken up now only if the scheduler predicts that no other job gets later; otherwise it waits.
// Handovers nobody answers are repeated with the same request id; a refused one waits and retries;
// a robot idle with the object of an opportunistic job aboard returns it to its pickup (the job
// fails with its reason); a cancelled job's object aboard is returned before the job ends.
// Fleet (fleet.cpp): robots join and leave while jobs run. A robot that joins is planned for from
// the next reschedule; one that leaves has its queued jobs reallocated to the others, and a job
// whose object it carried (or was handing over) becomes stranded, saying where the robot was last
// seen, until the robot comes back: then its unanswered handover is asked again and the job goes on.
#include "services/courier/core/execution/door_belief.hpp"
#include "services/courier/core/execution/floor.hpp"
#include "services/courier/core/execution/job.hpp"
#include "services/courier/core/execution/schedule_source.hpp"
#include "services/courier/core/knowledge/experience.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier {

struct ExecutiveSettings {
  double request_timeout_s = 5.0;    // an unanswered handover request is sent again (same id)
  double accepted_timeout_s = 60.0;  // an accepted one not completed by then is asked again (same id)
  double retry_after_s = 20.0;       // a refused handover (nobody present, helper busy) is retried
  double goal_retry_s = 1.0;         // a refused or preempted goal is sent again after this
  double goal_answer_s = 10.0;       // a goal its behavior never acknowledges is sent again
  double schedule_retry_s = 1.0;     // a schedule that failed as a whole is tried again after this
  int max_blocked_goals = 2;         // a place unreachable this often, no door to blame: its job fails
  // With several robots, a goal blocked by traffic ("no progress", or a robot named in the way)
  // says little about the place: the other robot moves on. Such a place is tried again after
  // traffic_retry_s (times the blocks so far) and given up only after this many blocks in a row.
  int max_traffic_blocked_goals = 6;
  double traffic_retry_s = 5.0;
  int max_attempts = 3;              // refused goals, failed or refused handovers of one step
  double goal_tolerance_m = 0.35;    // for navigation goals to places (within the place's radius)
  double home_retry_s = 30.0;        // an idle robot whose way home was blocked tries again after this
  // false: no door monitoring (the paper's heuristic alone, and what Open-RMF does): sightings
  // are not used, and a goal blocked by a closed door is sent again every door_wait_retry_s
  // until the door opens, never given up and never turned into an opportunity.
  bool monitor_doors = true;
  double door_wait_retry_s = 10.0;
  // A door seen closed and not seen since is assumed open again after this long: its
  // opportunistic jobs are tried again (without it they waited for a robot to pass by, and in
  // the day-in-office experiment one job in twelve was still waiting at the day's end).
  double closed_door_stale_s = 300.0;
  // An opportunistic job waiting for a door believed closed is given up this long after its
  // deadline passed (the policy's "deadline given up"): its object goes back to its pickup. Until
  // then the object stays aboard and the job waits for the door; negative: never given up for its
  // deadline (only when its person is gone for the day, or its place aboard is needed).
  double give_up_after_deadline_s = 900.0;
  // Part of every goal and request id, so that ids never repeat across runs of the service (a
  // simulator answers a repeated request id with its old answer). The node uses the journal's run.
  std::string id_tag = "r1";
  // The day of the once-per-day votes of what is learned (experience.hpp); the node changes it
  // with set_day() from the journal's run and the clock's midnights (a run is at least a day).
  std::int64_t day = 1;
};

// The goal place of a robot driving to where it parks (a parking spot of the floor, or home:
// where it joined the fleet); no place of the floor.
inline constexpr char kHomePlace[] = "@home";
// A robot this close to the parking spot it holds is parked (the goal tolerance of a place is
// smaller): out of everybody's way, holding no room.
inline constexpr double kParkedM = 1.0;
// The goal place of a robot waiting in sight of a door: "@lookout A-120" (Floor::door_lookouts).
inline constexpr char kLookoutPrefix[] = "@lookout ";
inline bool is_lookout(const std::string& place) { return place.rfind(kLookoutPrefix, 0) == 0; }
// The reason of a queued job the last schedule left out with no door to blame ("not in the
// schedule: cannot be done together with job 'job-3'"); cleared when a schedule has it.
inline constexpr char kNotScheduledPrefix[] = "not in the schedule: ";

struct NavGoalOrder {
  std::string robot;
  std::string goal_id;
  double x = 0.0, y = 0.0;
  double tolerance_m = 0.0;
};

// A navigation goal of ours that is no longer needed (its job went to another robot or ended): the
// robot stops instead of driving on into a room another robot may be bound for.
struct GoalCancelOrder {
  std::string robot;
  std::string goal_id;
  std::string reason;
};

struct HandoverOrder {
  std::string robot;
  std::string request_id;
  bool load = true;
  std::string place;
  std::string object_id;
  std::string job_id;
};

struct ScheduleNote {
  std::string robot;
  std::vector<PlanStop> stops;
  std::vector<std::string> assumptions;  // "A-120 open at 10:14:05"
  std::string engine;
  bool proved_optimal = false;
  int late_jobs = 0;
  double total_lateness_s = 0.0;
};

struct ReportNote {
  std::string job_id;
  std::string command_id;
  bool success = false;
  std::string text;
};

// One thing that happened, for logs, the events file and pictures (the paper's numbered steps).
struct ExecutionEvent {
  enum class Kind {
    accepted, revised, heading, loaded, unloaded, door_closed, door_opened, goal_blocked, goal_ended,
    handover_failed, handover_refused, failed_over, opportunity_taken, opportunity_declined, returning, finished,
    schedule_failed, robot_joined, robot_left, reallocated, stranded, resumed, goal_cancelled, waiting
  };
  Kind kind;
  std::string text;
};
const char* to_string(ExecutionEvent::Kind k);

// What the node must do after the events of a tick, in this order: journal and publish changed
// jobs, send handovers (journalled first) and goals, publish schedules and reports.
struct Orders {
  std::vector<std::string> changed_jobs;
  std::vector<HandoverOrder> handovers;
  std::vector<NavGoalOrder> goals;
  std::vector<GoalCancelOrder> cancels;
  std::vector<ScheduleNote> schedules;
  std::vector<ReportNote> reports;
  std::vector<ExecutionEvent> events;  // what happened, in order (logs, tests, pictures)
  bool empty() const {
    return changed_jobs.empty() && handovers.empty() && goals.empty() && cancels.empty() && schedules.empty() &&
           reports.empty() && events.empty();
  }
};

enum class GoalOutcome { accepted, active, reached, blocked, preempted, rejected, cancelled };
enum class HandoverOutcome { accepted, rejected, completed, failed };

class CourierExecutive {
 public:
  CourierExecutive(Floor floor, ScheduleSource& scheduler, ExecutiveSettings settings = {});

  // Joins the fleet (again): planned for once its pose is known. Stranded jobs whose object it
  // carries go on; its handover that was unanswered when it left is asked again (same id).
  void add_robot(const std::string& id, int capacity);
  // Leaves the fleet (`why`: "heartbeat lost", "stopped"): its jobs not aboard go back to the
  // others at the next reschedule, the jobs of objects aboard become stranded with its last place.
  void remove_robot(const std::string& id, const std::string& why, double now_s);
  bool has_robot(const std::string& id) const { return robots_.count(id) != 0; }
  std::vector<std::string> robot_ids() const;

  // A job accepted by the command front end (pickup, destination and object checked there).
  void add_job(Job job, double now_s);
  // Restores a journalled job as it was (restart after a crash); no events.
  void restore_job(Job job);
  // Restores a handover request that was sent but whose answer was not journalled: it is sent
  // again with the same id, and the simulator answers a repeat with its latest answer.
  // A robot not in the fleet yet gets it when it joins.
  void restore_pending_handover(const HandoverOrder& order);

  // Errors (unknown job, already finished, returning) as a reason; nothing on success.
  std::optional<std::string> cancel(const std::string& job_id, const std::string& reason, double now_s);
  std::optional<std::string> revise(const std::string& job_id, const std::optional<std::string>& destination,
                                    const std::optional<std::optional<double>>& deadline_s, double now_s);

  void on_pose(const std::string& robot, double x, double y);
  void on_door(const std::string& robot, const std::string& door_id, double angle_rad, double now_s);
  void on_goal(const std::string& robot, const std::string& goal_id, GoalOutcome outcome,
               const std::string& reason, double now_s);
  void on_handover(const std::string& request_id, HandoverOutcome outcome, const std::string& reason,
                   const std::string& detail, double now_s);

  // Once per tick, after the tick's events: reschedules when an assumption broke or the job set
  // changed, dispatches each robot's next activity, and hands over the orders.
  Orders step(double now_s);
  // After step(): nullopt while there is work (a robot driving, handing over, a stop to go to,
  // something to plan); otherwise the time before which step() would do nothing unless an event
  // above comes (a hold ending, a failed schedule's retry, a closed door's sighting going stale;
  // infinity when none). idle.cpp.
  std::optional<double> idle_until_s(double now_s) const;

  const std::map<std::string, Job>& jobs() const { return jobs_; }
  const Job* job(const std::string& id) const;
  // The unfinished job that holds `object_id`, if any: one object is in one open job at a time.
  const Job* open_job_of_object(const std::string& object_id) const;
  // Where each object of a job is believed to be now (place or carrier), from its latest job:
  // deliveries and returns move what the courier knows of its objects. objects.cpp.
  struct ObjectWhereabouts {
    std::string place;
    std::string carrier;
    std::string job;  // the job whose belief this is
  };
  std::map<std::string, ObjectWhereabouts> object_whereabouts() const;
  const DoorBelief& doors() const { return doors_; }
  // What experience taught so far (handover times, presence, doors by time of day, travel
  // times): recorded from the events above; restored from the journal at start.
  // Observations from now on vote as `day` (ExecutiveSettings::day).
  void set_day(std::int64_t day) { settings_.day = day; }
  const Experience& experience() const { return experience_; }
  Experience& experience() { return experience_; }
  std::vector<PlanStop> route(const std::string& robot) const;

 private:
  struct PendingHandover {
    HandoverOrder order;
    double sent_at_s = 0.0;
    bool accepted = false;
    double accepted_at_s = 0.0;
  };
  struct Robot {
    std::string id;
    int capacity = 1;
    bool pose_known = false;
    double x = 0.0, y = 0.0;
    std::string goal_id;     // the navigation goal it pursues for us
    std::string goal_place;  // where that goal leads
    std::string goal_from;   // the place it set out from ("" if none), for learned travel times
    double goal_sent_s = 0.0;
    bool goal_answered = false;  // the behavior said anything about goal_id
    std::string at_place;    // the place its last goal reached
    std::optional<PendingHandover> handover;
    std::vector<PlanStop> route;
    double hold_until_s = 0.0;  // after a refused handover or goal
    // The place whose person is away until hold_until_s: a new schedule that sends the robot
    // elsewhere first ends the wait (the robot works while the person is out). Set with hold().
    std::string held_for;
    // Waits until `until_s`; for the person at `place` when given.
    void hold(double until_s, std::string place = {}) {
      hold_until_s = until_s;
      held_for = std::move(place);
    }
    int goal_seq = 0;
    int request_seq = 0;
    std::map<std::string, int> blocked;  // place -> blocked goals without a door to blame
    std::map<std::string, int> refused;  // place -> refused or preempted goals in a row
    // Where it joined the fleet (its first pose): with several robots, an idle one goes back
    // there, out of the others' way (a robot stopped in the hallway blocks a doorway).
    bool home_known = false;
    double home_x = 0.0, home_y = 0.0;
    // The parking spot it holds (Floor::parking) from being parked until it is sent elsewhere.
    std::string parking;
    // The room its next stop is in, while another robot holds that room (room_claims.cpp), and
    // since when it waits: robots waiting for one room go in the order they began to wait.
    std::string waiting_for_room;
    double waiting_since_s = 0.0;
    std::string waiting_behind;  // the robot it waits for, as last reported
  };

  void reschedule(double now_s);
  PlanRequest request_for(double now_s, const std::vector<std::string>& extra_jobs) const;
  void adopt(const Plan& plan, double now_s);
  void opportunity_check(double now_s);
  void dispatch(Robot& robot, double now_s);
  // Nothing else to do: objects aboard whose job waits for a door stay aboard and the robot waits
  // in sight of that door; a job whose door is believed open again is taken up. opportunistic.cpp.
  // True when the robot is kept busy so (not to be parked).
  bool idle_policy(Robot& robot, double now_s);
  // Opportunistic jobs that can no longer be done are ended (objects aboard go back): the deadline
  // given up by the policy. opportunistic.cpp.
  void give_up_overdue(double now_s);
  // A job is given up for good: an object aboard goes back to its pickup, otherwise it fails.
  void give_up_job(Job& job, const std::string& reason, double now_s);
  // Objects of opportunistic jobs aboard a robot whose place aboard a job the plan left out needs:
  // they go back, and the job is planned. opportunistic.cpp.
  bool make_room(const Plan& plan, double now_s);
  // A return started because a door stayed closed, for a door now seen open: delivered after all.
  void reconsider_returns(const std::string& door_id, double now_s);
  // Sends `robot` to the lookout of `door` (when the floor has one and it is not there).
  void watch_door(Robot& robot, const std::string& door, double now_s);
  // Nothing to do: to a parking spot or home (several robots), or stop (cancel a goal no longer
  // needed). fleet.cpp.
  // `why` ends its heading event ("rhino parks at ..., out of the way: <why>").
  void park(Robot& robot, double now_s, const std::string& why = "nothing for it now");
  struct ParkingPlace {
    double x = 0.0, y = 0.0;
    std::string spot;  // "" for the robot's home
  };
  // Where an idle robot of a fleet waits: the spot it holds, else the nearest spot that no other
  // robot holds or stands at (it then holds it), else where it joined the fleet. fleet.cpp.
  std::optional<ParkingPlace> parking_place(Robot& robot);
  // Fleet rule: one robot in a room at a time (rooms with doors: a desk, a doorway and the space
  // to turn around are all for one robot). True when `robot` must wait before driving to `stop`:
  // another robot is in that room or bound for it, or waited for it first. The robot then waits
  // beside the room's door (the first in line) or parked (else where it is), and the job says
  // for whom.
  // `waited`: the room it waited for until this step. room_claims.cpp.
  bool wait_for_room(Robot& robot, const PlanStop& stop, const std::string& waited, double now_s);
  // The robot other than `robot` that holds `claim` (a room, or a place in the hallway): bound
  // for a place in it, handing over in it, or inside its area (on the place) and not parked.
  // nullptr when it is free.
  const Robot* room_holder(const Robot& robot, const std::string& claim) const;
  // What a robot bound for `place` claims: its room when a door leads into it, else the place
  // itself (a handover place in the hallway); "" for a place the floor does not have.
  std::string claim_of(const std::string& place) const;
  bool within_claim(const std::string& claim, const std::string& place) const;
  // When `robot` may set out, as the scheduler should see it: now, or while it waits for a room,
  // when the robot holding it is expected to have left (the end of its planned stops there).
  double free_to_go_s(const Robot& robot, double now_s) const;
  // Sends `robot` to the lookout beside `door` (when the floor has one and it is not there),
  // saying `why` in the heading event. False when the door has no lookout (it waits where it is).
  bool go_to_lookout(Robot& robot, const std::string& door, const std::string& why, double now_s);
  void send_goal(Robot& robot, const std::string& place, double now_s);
  void send_handover(Robot& robot, const PlanStop& stop, double now_s);
  bool at(const Robot& robot, const std::string& place) const;
  // True when `stop` is still the job's next step on this robot.
  bool still_needed(const Robot& robot, const PlanStop& stop) const;
  void make_opportunistic(Job& job, const std::string& reason, double now_s);
  // Ends unfinished jobs whose object is where it should be (e.g. a cancel during a load that then
  // failed leaves the object at its pickup, which is where a return would take it).
  void settle(double now_s);
  // The handover order of some robot that is in flight for `job_id`, if any.
  const HandoverOrder* handover_in_flight(const std::string& job_id) const;
  // Jobs with a next step at `place` that no robot is handing over now: fail them (returning what
  // is aboard) with `reason`.
  void give_up_on(const std::string& place, const std::string& reason, double now_s);
  // Counts one more failed attempt at `key`; true when that was the last allowed.
  bool exhausted(std::map<std::string, int>& counts, const std::string& key);
  void start_return(Job& job, JobState end_state, const std::string& reason, double now_s);
  void finish(Job& job, JobState state, const std::string& reason, double now_s);
  void changed(const Job& job);
  void event(ExecutionEvent::Kind kind, std::string text);
  // Who hands over at `place` ("" for stations), for what is learned about people.
  std::string person_at(const std::string& place) const;
  // The door that a step at `place` needs open, when it is believed closed.
  std::optional<std::string> closed_door_for(const std::string& place) const;
  std::string closed_reason(const std::string& door) const;
  // "at (12.3, 4.5) near a114-desk in A-114": a robot's last known place, for stranded objects.
  std::string last_seen(const Robot& robot) const;

  Floor floor_;
  ScheduleSource& scheduler_;
  ExecutiveSettings settings_;
  DoorBelief doors_;
  Experience experience_;
  std::map<std::string, Robot> robots_;
  // Robots that left: their request counters (ids never repeat) and unanswered handover, kept
  // for when they come back.
  std::map<std::string, Robot> departed_;
  std::vector<HandoverOrder> restored_handovers_;  // for robots that have not joined yet
  std::map<std::string, Job> jobs_;
  bool reschedule_needed_ = false;
  std::optional<double> schedule_retry_at_;  // after a schedule failed as a whole
  std::map<std::string, int> handover_attempts_;  // "job/load|unload" -> failed or refused tries
  bool opportunity_pending_ = false;
  Orders orders_;
};

// "10:14:05" for seconds of the day.
std::string clock_text(double seconds_of_day);

}  // namespace autonomy::courier
