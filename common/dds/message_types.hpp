#pragma once
// DdsType specialisations for every message of idl/: which generated C type carries it.
// Conversions live in conversions/<area>.cpp, one file per IDL file.
#include "common/dds/type_traits.hpp"
#include "common/msg/clock.hpp"
#include "common/msg/courier.hpp"
#include "common/msg/executive.hpp"
#include "common/msg/navigation.hpp"
#include "common/msg/office.hpp"
#include "common/msg/planner.hpp"
#include "common/msg/robot.hpp"
#include "common/msg/simulation.hpp"
#include "common/msg/perception.hpp"
#include "common/msg/radio.hpp"
#include "common/msg/truth.hpp"
#include "common/msg/system.hpp"
#include "common/msg/spacecraft.hpp"
#include "idl/clock.h"
#include "idl/courier.h"
#include "idl/executive.h"
#include "idl/navigation.h"
#include "idl/office.h"
#include "idl/planner.h"
#include "idl/robot.h"
#include "idl/simulation.h"
#include "idl/perception.h"
#include "idl/radio.h"
#include "idl/truth.h"
#include "idl/system.h"
#include "idl/spacecraft.h"

#define AUTONOMY_DDS_TYPE(VALUE, CTYPE)                                                  \
  template <>                                                                            \
  struct DdsType<VALUE> {                                                                \
    using C = CTYPE;                                                                     \
    static const dds_topic_descriptor_t* descriptor() { return &CTYPE##_desc; }          \
    static const char* type_name() { return CTYPE##_desc.m_typename; }                   \
    static void to_c(const VALUE& value, C& out, Arena& arena);                          \
    static VALUE from_c(const C& in);                                                    \
  };

namespace autonomy::dds {

// sequence<string> fields: the C sequence points into `v` and into `arena` (see Arena).
inline dds_sequence_string to_c_strings(const std::vector<std::string>& v, Arena& arena) {
  const uint32_t n = static_cast<uint32_t>(v.size());
  auto* names = arena.allocate<char*>(n);
  for (uint32_t i = 0; i < n; ++i) names[i] = c_str(v[i]);
  return {n, n, names, false};
}

inline std::vector<std::string> from_c_strings(const dds_sequence_string& s) {
  std::vector<std::string> v;
  v.reserve(s._length);
  for (uint32_t i = 0; i < s._length; ++i) v.push_back(from_c_str(s._buffer[i]));
  return v;
}

AUTONOMY_DDS_TYPE(msg::Heartbeat, autonomy_Heartbeat)
AUTONOMY_DDS_TYPE(msg::SimClock, autonomy_SimClock)
AUTONOMY_DDS_TYPE(msg::LockstepRegistration, autonomy_LockstepRegistration)
AUTONOMY_DDS_TYPE(msg::TickAck, autonomy_TickAck)
AUTONOMY_DDS_TYPE(msg::RobotState, autonomy_RobotState)
AUTONOMY_DDS_TYPE(msg::VelocityCommand, autonomy_VelocityCommand)
AUTONOMY_DDS_TYPE(msg::CommandRejection, autonomy_CommandRejection)
AUTONOMY_DDS_TYPE(msg::SpawnRequest, autonomy_SpawnRequest)
AUTONOMY_DDS_TYPE(msg::SpawnReply, autonomy_SpawnReply)
AUTONOMY_DDS_TYPE(msg::WorldMap, autonomy_WorldMap)
AUTONOMY_DDS_TYPE(msg::SimulatorStatus, autonomy_SimulatorStatus)
AUTONOMY_DDS_TYPE(msg::NavGoal, autonomy_NavGoal)
AUTONOMY_DDS_TYPE(msg::GoalStatus, autonomy_GoalStatus)
// Simulator world v2: perception, ground truth, radio, team messages, door commands.
AUTONOMY_DDS_TYPE(msg::RangeScan, autonomy_RangeScan)
AUTONOMY_DDS_TYPE(msg::PoseEstimate, autonomy_PoseEstimate)
AUTONOMY_DDS_TYPE(msg::DoorObservation, autonomy_DoorObservation)
AUTONOMY_DDS_TYPE(msg::DoorState, autonomy_DoorState)
AUTONOMY_DDS_TYPE(msg::RadioLink, autonomy_RadioLink)
AUTONOMY_DDS_TYPE(msg::TeamConnectivity, autonomy_TeamConnectivity)
AUTONOMY_DDS_TYPE(msg::TeamMessage, autonomy_TeamMessage)
AUTONOMY_DDS_TYPE(msg::TeamDelivery, autonomy_TeamDelivery)
AUTONOMY_DDS_TYPE(msg::DoorCommand, autonomy_DoorCommand)
AUTONOMY_DDS_TYPE(msg::NavCancel, autonomy_NavCancel)
AUTONOMY_DDS_TYPE(msg::MissionStatus, autonomy_MissionStatus)
AUTONOMY_DDS_TYPE(msg::Itinerary, autonomy_Itinerary)
// The office: load/unload requests and answers, object ground truth.
AUTONOMY_DDS_TYPE(msg::HandoverRequest, autonomy_HandoverRequest)
AUTONOMY_DDS_TYPE(msg::HandoverStatus, autonomy_HandoverStatus)
AUTONOMY_DDS_TYPE(msg::ObjectState, autonomy_ObjectState)
// The courier scheduler: commands and replies, job states, schedules, reports.
AUTONOMY_DDS_TYPE(msg::CourierCommand, autonomy_CourierCommand)
AUTONOMY_DDS_TYPE(msg::CourierReply, autonomy_CourierReply)
AUTONOMY_DDS_TYPE(msg::CourierJobStatus, autonomy_CourierJobStatus)
AUTONOMY_DDS_TYPE(msg::CourierSchedule, autonomy_CourierSchedule)
AUTONOMY_DDS_TYPE(msg::CourierReport, autonomy_CourierReport)
// The spacecraft (idl/spacecraft.idl).
AUTONOMY_DDS_TYPE(msg::SpacecraftCommand, autonomy_SpacecraftCommand)
AUTONOMY_DDS_TYPE(msg::SpacecraftCommandStatus, autonomy_SpacecraftCommandStatus)
AUTONOMY_DDS_TYPE(msg::SpacecraftTelemetry, autonomy_SpacecraftTelemetry)
AUTONOMY_DDS_TYPE(msg::SpacecraftFaultInjection, autonomy_SpacecraftFaultInjection)
AUTONOMY_DDS_TYPE(msg::SpacecraftFaultState, autonomy_SpacecraftFaultState)
AUTONOMY_DDS_TYPE(msg::SpacecraftEvent, autonomy_SpacecraftEvent)
// The planner: requests, replies, progress, cancellation, the latest plan per requester.
AUTONOMY_DDS_TYPE(msg::PlanningRequest, autonomy_PlanningRequest)
AUTONOMY_DDS_TYPE(msg::PlanningReply, autonomy_PlanningReply)
AUTONOMY_DDS_TYPE(msg::PlanningProgress, autonomy_PlanningProgress)
AUTONOMY_DDS_TYPE(msg::PlanningCancel, autonomy_PlanningCancel)
AUTONOMY_DDS_TYPE(msg::LatestPlan, autonomy_LatestPlan)
// The executive: its events and status.
AUTONOMY_DDS_TYPE(msg::ExecutiveEvent, autonomy_ExecutiveEvent)
AUTONOMY_DDS_TYPE(msg::ExecutiveStatus, autonomy_ExecutiveStatus)

}  // namespace autonomy::dds

#undef AUTONOMY_DDS_TYPE
