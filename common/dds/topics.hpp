#pragma once
// The catalogue of topics: one line per topic, its type and QoS class. docs/topics.md describes
// the same list for people (writers, readers, keys); keep both in step.
#include "common/dds/message_types.hpp"
#include "common/dds/topic.hpp"

namespace autonomy::dds::topics {

inline constexpr TopicSpec<msg::Heartbeat> heartbeat{"autonomy/heartbeat", QosClass::State};

inline constexpr TopicSpec<msg::SimClock> clock{"autonomy/clock", QosClass::State};
inline constexpr TopicSpec<msg::LockstepRegistration> lockstep_registration{"autonomy/lockstep/registration",
                                                                            QosClass::State};
inline constexpr TopicSpec<msg::TickAck> tick_ack{"autonomy/lockstep/ack", QosClass::Event};

inline constexpr TopicSpec<msg::RobotState> robot_state{"autonomy/robot/state", QosClass::State};
inline constexpr TopicSpec<msg::VelocityCommand> cmd_vel{"autonomy/robot/cmd_vel", QosClass::Command};
inline constexpr TopicSpec<msg::CommandRejection> command_rejected{"autonomy/sim/command_rejected", QosClass::Event};

inline constexpr TopicSpec<msg::SpawnRequest> spawn_request{"autonomy/sim/spawn_request", QosClass::Request};
inline constexpr TopicSpec<msg::SpawnReply> spawn_reply{"autonomy/sim/spawn_reply", QosClass::Reply};
inline constexpr TopicSpec<msg::WorldMap> world_map{"autonomy/map", QosClass::State};
inline constexpr TopicSpec<msg::SimulatorStatus> sim_status{"autonomy/sim/status", QosClass::State};

inline constexpr TopicSpec<msg::NavGoal> nav_goal{"autonomy/nav/goal", QosClass::Command};
inline constexpr TopicSpec<msg::GoalStatus> goal_status{"autonomy/nav/goal_status", QosClass::State};

// What robots sense (the simulator's sensor models), per robot.
inline constexpr TopicSpec<msg::RangeScan> range_scan{"autonomy/robot/range_scan", QosClass::Stream};
inline constexpr TopicSpec<msg::PoseEstimate> pose_estimate{"autonomy/robot/pose_estimate", QosClass::Stream};
inline constexpr TopicSpec<msg::DoorObservation> door_observation{"autonomy/robot/door_observation",
                                                                  QosClass::Event};
// Ground truth nobody senses directly (robot ground truth is robot_state).
inline constexpr TopicSpec<msg::DoorState> truth_door{"autonomy/truth/door", QosClass::State};
// The simulated radio and the team messages it relays; door commands for experiments.
inline constexpr TopicSpec<msg::RadioLink> radio_link{"autonomy/radio/link", QosClass::State};
inline constexpr TopicSpec<msg::TeamConnectivity> radio_team{"autonomy/radio/team", QosClass::State};
inline constexpr TopicSpec<msg::TeamMessage> team_outbox{"autonomy/team/outbox", QosClass::Event};
inline constexpr TopicSpec<msg::TeamDelivery> team_inbox{"autonomy/team/inbox", QosClass::Event};
inline constexpr TopicSpec<msg::DoorCommand> door_command{"autonomy/sim/door_command", QosClass::Command};
inline constexpr TopicSpec<msg::NavCancel> nav_cancel{"autonomy/nav/cancel", QosClass::Command};
inline constexpr TopicSpec<msg::MissionStatus> mission_status{"autonomy/mission/status", QosClass::State};
// Fleet traffic (docs/traffic.md): each behavior's path with times, footprint and passage claim.
inline constexpr TopicSpec<msg::Itinerary> itinerary{"autonomy/nav/itinerary", QosClass::State};
// The office: robots ask the simulator to load and unload objects; where every object is (truth).
inline constexpr TopicSpec<msg::HandoverRequest> handover_request{"autonomy/office/handover_request",
                                                                  QosClass::Request};
inline constexpr TopicSpec<msg::HandoverStatus> handover_status{"autonomy/office/handover_status", QosClass::Reply};
inline constexpr TopicSpec<msg::ObjectState> truth_object{"autonomy/truth/object", QosClass::State};
// The courier scheduler: commands in, replies, job states, schedules, top-level reports out.
inline constexpr TopicSpec<msg::CourierCommand> courier_command{"autonomy/courier/command", QosClass::Request};
inline constexpr TopicSpec<msg::CourierReply> courier_reply{"autonomy/courier/reply", QosClass::Reply};
inline constexpr TopicSpec<msg::CourierJobStatus> courier_job_status{"autonomy/courier/job_status",
                                                                     QosClass::State};
inline constexpr TopicSpec<msg::CourierSchedule> courier_schedule{"autonomy/courier/schedule", QosClass::State};
inline constexpr TopicSpec<msg::CourierReport> courier_report{"autonomy/courier/report", QosClass::Event};
// The spacecraft (docs/spacecraft.md): device commands and their status, telemetry, faults.
inline constexpr TopicSpec<msg::SpacecraftCommand> spacecraft_command{"autonomy/spacecraft/command",
                                                                      QosClass::Queue};
inline constexpr TopicSpec<msg::SpacecraftCommandStatus> spacecraft_command_status{
    "autonomy/spacecraft/command_status", QosClass::Queue};
inline constexpr TopicSpec<msg::SpacecraftTelemetry> spacecraft_telemetry{"autonomy/spacecraft/telemetry",
                                                                          QosClass::State};
inline constexpr TopicSpec<msg::SpacecraftFaultInjection> spacecraft_fault_injection{
    "autonomy/spacecraft/fault_injection", QosClass::Command};
inline constexpr TopicSpec<msg::SpacecraftFaultState> truth_spacecraft_fault{"autonomy/truth/spacecraft_fault",
                                                                             QosClass::State};
inline constexpr TopicSpec<msg::SpacecraftEvent> spacecraft_event{"autonomy/spacecraft/event", QosClass::Event};
// The planner: requests in, one reply each, progress of long searches, cancels, latest plans.
inline constexpr TopicSpec<msg::PlanningRequest> planner_request{"autonomy/planner/request", QosClass::Request};
inline constexpr TopicSpec<msg::PlanningReply> planner_reply{"autonomy/planner/reply", QosClass::Reply};
inline constexpr TopicSpec<msg::PlanningProgress> planner_progress{"autonomy/planner/progress", QosClass::Event};
inline constexpr TopicSpec<msg::PlanningCancel> planner_cancel{"autonomy/planner/cancel", QosClass::Command};
inline constexpr TopicSpec<msg::LatestPlan> planner_plan{"autonomy/planner/plan", QosClass::State};
// The executive: what it did and why (events), and where it is (status, one per executive).
inline constexpr TopicSpec<msg::ExecutiveEvent> executive_event{"autonomy/executive/event", QosClass::Event};
inline constexpr TopicSpec<msg::ExecutiveStatus> executive_status{"autonomy/executive/status", QosClass::State};

// Calls visit(spec) for every topic of the catalogue: tools use it to find a topic's type by name.
template <typename Visitor>
void for_each_topic(Visitor&& visit) {
  visit(heartbeat);
  visit(clock);
  visit(lockstep_registration);
  visit(tick_ack);
  visit(robot_state);
  visit(cmd_vel);
  visit(command_rejected);
  visit(spawn_request);
  visit(spawn_reply);
  visit(world_map);
  visit(sim_status);
  visit(nav_goal);
  visit(goal_status);
  visit(range_scan);
  visit(pose_estimate);
  visit(door_observation);
  visit(truth_door);
  visit(radio_link);
  visit(radio_team);
  visit(team_outbox);
  visit(team_inbox);
  visit(door_command);
  visit(nav_cancel);
  visit(mission_status);
  visit(itinerary);
  visit(handover_request);
  visit(handover_status);
  visit(truth_object);
  visit(courier_command);
  visit(courier_reply);
  visit(courier_job_status);
  visit(courier_schedule);
  visit(courier_report);
  visit(spacecraft_command);
  visit(spacecraft_command_status);
  visit(spacecraft_telemetry);
  visit(spacecraft_fault_injection);
  visit(truth_spacecraft_fault);
  visit(spacecraft_event);
  visit(planner_request);
  visit(planner_reply);
  visit(planner_progress);
  visit(planner_cancel);
  visit(planner_plan);
  visit(executive_event);
  visit(executive_status);
}

}  // namespace autonomy::dds::topics
