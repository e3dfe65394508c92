#pragma once
// C++ value types of idl/simulation.idl.
#include "common/geometry/geometry.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace autonomy::msg {

struct SpawnRequest {
  std::string request_id;
  std::string requester;
  std::string robot_id;
  bool has_pose = false;
  double x = 0.0, y = 0.0, theta = 0.0;
};

enum class RequestStatus { Accepted, Rejected };

struct SpawnReply {
  std::string request_id;
  std::string robot_id;
  RequestStatus status = RequestStatus::Rejected;
  std::string reason;
};

struct MapPoint {
  double x = 0.0;
  double y = 0.0;
};

struct MapPolygon {
  std::string name;
  std::vector<MapPoint> vertices;
};

// An occupancy raster in the world frame; `blocked` holds cols * rows bytes (1 = blocked),
// row-major from the bottom row. (Run-length coded on the wire: see idl/simulation.idl.)
// A received raster of more than kMaxMapRasterCells cells (a 16,000 x 16,000 map) arrives empty.
inline constexpr std::size_t kMaxMapRasterCells = std::size_t{1} << 28;
struct MapRaster {
  std::string name;
  double origin_x = 0.0;
  double origin_y = 0.0;
  double resolution = 1.0;
  uint32_t cols = 0;
  uint32_t rows = 0;
  std::vector<uint8_t> blocked;
};

// A doorway: `width` m centred at (x, y) along `heading` (rad, hinge to latch); its leaf, when
// open, turned `open_angle` (rad, signed, + counter-clockwise) about the hinge (0: not said).
struct MapDoor {
  std::string id;
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double heading = 0.0;
  double open_angle = 0.0;
};

struct WorldMap {
  std::string name;
  double width = 0.0;
  double height = 0.0;
  std::vector<geometry::Rect> obstacles;
  std::vector<MapPolygon> polygons;
  std::vector<MapRaster> rasters;
  std::vector<MapDoor> doors;
};

// A lockstep participant dropped (no ack within the timeout) or rejoined (idl/simulation.idl).
struct LockstepChange {
  uint64_t number = 0;
  int64_t tick = 0;
  std::string participant;
  bool dropped = false;
  std::string reason;
};

struct SimulatorStatus {
  int64_t tick = 0;
  int64_t sim_time_ns = 0;
  uint32_t robots = 0;
  std::vector<std::string> lockstep_participants;
  uint64_t commands_applied = 0;
  uint64_t commands_rejected = 0;
  uint64_t participants_dropped = 0;
  double mean_step_us = 0.0;
  uint64_t team_messages_delivered = 0;
  uint64_t team_messages_dropped_no_route = 0;
  uint64_t team_messages_dropped_lost = 0;
  uint64_t team_messages_dropped_invalid = 0;
  std::vector<std::string> lockstep_dropped;
  std::vector<LockstepChange> lockstep_changes;
};

struct DoorCommand {
  std::string door_id;
  double angle = 0.0;
  std::string source;
};

const char* to_string(RequestStatus s);

}  // namespace autonomy::msg
