#include "common/dds/message_types.hpp"

#include <algorithm>
#include <vector>

namespace autonomy::dds {

void DdsType<msg::SpawnRequest>::to_c(const msg::SpawnRequest& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.requester = c_str(v.requester);
  out.robot_id = c_str(v.robot_id);
  out.has_pose = v.has_pose;
  out.x = v.x;
  out.y = v.y;
  out.theta = v.theta;
}

msg::SpawnRequest DdsType<msg::SpawnRequest>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.requester), from_c_str(in.robot_id), in.has_pose, in.x, in.y,
          in.theta};
}

void DdsType<msg::SpawnReply>::to_c(const msg::SpawnReply& v, C& out, Arena&) {
  out.request_id = c_str(v.request_id);
  out.robot_id = c_str(v.robot_id);
  out.status = static_cast<autonomy_RequestStatus>(v.status);
  out.reason = c_str(v.reason);
}

msg::SpawnReply DdsType<msg::SpawnReply>::from_c(const C& in) {
  return {from_c_str(in.request_id), from_c_str(in.robot_id), static_cast<msg::RequestStatus>(in.status),
          from_c_str(in.reason)};
}

namespace {

// Run-length code of a raster's cells (see MapRaster in idl/simulation.idl): alternating runs of
// free and blocked cells, the first run free (possibly empty).
std::vector<uint32_t> runs_of(const std::vector<uint8_t>& blocked) {
  std::vector<uint32_t> runs;
  uint8_t current = 0;
  uint32_t length = 0;
  for (const uint8_t cell : blocked) {
    const uint8_t b = cell != 0 ? 1 : 0;
    if (b != current) {
      runs.push_back(length);
      current = b;
      length = 0;
    }
    ++length;
  }
  runs.push_back(length);
  return runs;
}

// The cells of a run-length code; a code that does not add up to cols * rows is cut or padded
// with free cells, so a bad sample cannot make a reader overrun or allocate without bound.
std::vector<uint8_t> cells_of(const uint32_t* runs, uint32_t count, std::size_t cells) {
  std::vector<uint8_t> blocked(cells, 0);
  std::size_t at = 0;
  for (uint32_t i = 0; i < count && at < cells; ++i) {
    const std::size_t n = std::min<std::size_t>(runs[i], cells - at);
    if (i % 2 == 1) std::fill_n(blocked.begin() + static_cast<std::ptrdiff_t>(at), n, uint8_t{1});
    at += n;
  }
  return blocked;
}

}  // namespace

void DdsType<msg::WorldMap>::to_c(const msg::WorldMap& v, C& out, Arena& arena) {
  out.name = c_str(v.name);
  out.width = v.width;
  out.height = v.height;
  const uint32_t n = static_cast<uint32_t>(v.obstacles.size());
  auto* rects = arena.allocate<autonomy_Rectangle>(n);
  for (uint32_t i = 0; i < n; ++i) {
    const auto& r = v.obstacles[i];
    rects[i] = {r.min_x, r.min_y, r.max_x, r.max_y};
  }
  out.obstacles = {n, n, rects, false};

  const uint32_t np = static_cast<uint32_t>(v.polygons.size());
  auto* polygons = arena.allocate<autonomy_MapPolygon>(np);
  for (uint32_t i = 0; i < np; ++i) {
    const auto& p = v.polygons[i];
    const uint32_t nv = static_cast<uint32_t>(p.vertices.size());
    auto* vertices = arena.allocate<autonomy_MapPoint>(nv);
    for (uint32_t k = 0; k < nv; ++k) vertices[k] = {p.vertices[k].x, p.vertices[k].y};
    polygons[i].name = c_str(p.name);
    polygons[i].vertices = {nv, nv, vertices, false};
  }
  out.polygons = {np, np, polygons, false};

  const uint32_t nr = static_cast<uint32_t>(v.rasters.size());
  auto* rasters = arena.allocate<autonomy_MapRaster>(nr);
  for (uint32_t i = 0; i < nr; ++i) {
    const auto& r = v.rasters[i];
    const std::vector<uint32_t> runs = runs_of(r.blocked);
    const uint32_t nruns = static_cast<uint32_t>(runs.size());
    auto* buffer = arena.allocate<uint32_t>(nruns);
    std::copy(runs.begin(), runs.end(), buffer);
    rasters[i].name = c_str(r.name);
    rasters[i].origin_x = r.origin_x;
    rasters[i].origin_y = r.origin_y;
    rasters[i].resolution = r.resolution;
    rasters[i].cols = r.cols;
    rasters[i].rows = r.rows;
    rasters[i].runs = {nruns, nruns, buffer, false};
  }
  out.rasters = {nr, nr, rasters, false};

  const uint32_t nd = static_cast<uint32_t>(v.doors.size());
  auto* doors = arena.allocate<autonomy_MapDoor>(nd);
  for (uint32_t i = 0; i < nd; ++i) {
    const auto& d = v.doors[i];
    doors[i] = {c_str(d.id), d.x, d.y, d.width, d.heading, d.open_angle};
  }
  out.doors = {nd, nd, doors, false};
}

msg::WorldMap DdsType<msg::WorldMap>::from_c(const C& in) {
  msg::WorldMap v;
  v.name = from_c_str(in.name);
  v.width = in.width;
  v.height = in.height;
  v.obstacles.reserve(in.obstacles._length);
  for (uint32_t i = 0; i < in.obstacles._length; ++i) {
    const auto& r = in.obstacles._buffer[i];
    v.obstacles.push_back({r.min_x, r.min_y, r.max_x, r.max_y});
  }
  for (uint32_t i = 0; i < in.polygons._length; ++i) {
    const auto& p = in.polygons._buffer[i];
    msg::MapPolygon polygon{from_c_str(p.name), {}};
    for (uint32_t k = 0; k < p.vertices._length; ++k) {
      polygon.vertices.push_back({p.vertices._buffer[k].x, p.vertices._buffer[k].y});
    }
    v.polygons.push_back(std::move(polygon));
  }
  for (uint32_t i = 0; i < in.rasters._length; ++i) {
    const auto& r = in.rasters._buffer[i];
    msg::MapRaster raster{from_c_str(r.name), r.origin_x, r.origin_y, r.resolution, r.cols, r.rows, {}};
    const std::size_t cells = static_cast<std::size_t>(r.cols) * r.rows;
    std::size_t coded = 0;
    for (uint32_t k = 0; k < r.runs._length; ++k) coded += r.runs._buffer[k];
    // Allocate only what the runs describe: a sample claiming huge dimensions with few runs
    // keeps its claimed size only if the runs cover it, and only up to kMaxMapRasterCells (a few
    // huge runs could otherwise ask for more memory than the reader has).
    const bool plausible = cells <= msg::kMaxMapRasterCells;
    raster.blocked = plausible ? cells_of(r.runs._buffer, r.runs._length, std::min(cells, coded))
                               : std::vector<uint8_t>{};
    if (raster.blocked.size() != cells) {
      raster.cols = 0;  // inconsistent sample: readers see an empty raster rather than a wrong one
      raster.rows = 0;
      raster.blocked.clear();
    }
    v.rasters.push_back(std::move(raster));
  }
  for (uint32_t i = 0; i < in.doors._length; ++i) {
    const auto& d = in.doors._buffer[i];
    v.doors.push_back({from_c_str(d.id), d.x, d.y, d.width, d.heading, d.open_angle});
  }
  return v;
}

void DdsType<msg::SimulatorStatus>::to_c(const msg::SimulatorStatus& v, C& out, Arena& arena) {
  out.tick = v.tick;
  out.sim_time_ns = v.sim_time_ns;
  out.robots = v.robots;
  out.lockstep_participants = to_c_strings(v.lockstep_participants, arena);
  out.commands_applied = v.commands_applied;
  out.commands_rejected = v.commands_rejected;
  out.participants_dropped = v.participants_dropped;
  out.mean_step_us = v.mean_step_us;
  out.team_messages_delivered = v.team_messages_delivered;
  out.team_messages_dropped_no_route = v.team_messages_dropped_no_route;
  out.team_messages_dropped_lost = v.team_messages_dropped_lost;
  out.team_messages_dropped_invalid = v.team_messages_dropped_invalid;
  out.lockstep_dropped = to_c_strings(v.lockstep_dropped, arena);
  const auto nc = static_cast<uint32_t>(v.lockstep_changes.size());
  auto* changes = arena.allocate<autonomy_LockstepChange>(nc);
  for (uint32_t i = 0; i < nc; ++i) {
    const msg::LockstepChange& c = v.lockstep_changes[i];
    changes[i] = {c.number, c.tick, c_str(c.participant), c.dropped, c_str(c.reason)};
  }
  out.lockstep_changes = {nc, nc, changes, false};
}

msg::SimulatorStatus DdsType<msg::SimulatorStatus>::from_c(const C& in) {
  msg::SimulatorStatus v;
  v.tick = in.tick;
  v.sim_time_ns = in.sim_time_ns;
  v.robots = in.robots;
  v.lockstep_participants = from_c_strings(in.lockstep_participants);
  v.commands_applied = in.commands_applied;
  v.commands_rejected = in.commands_rejected;
  v.participants_dropped = in.participants_dropped;
  v.mean_step_us = in.mean_step_us;
  v.team_messages_delivered = in.team_messages_delivered;
  v.team_messages_dropped_no_route = in.team_messages_dropped_no_route;
  v.team_messages_dropped_lost = in.team_messages_dropped_lost;
  v.team_messages_dropped_invalid = in.team_messages_dropped_invalid;
  v.lockstep_dropped = from_c_strings(in.lockstep_dropped);
  for (uint32_t i = 0; i < in.lockstep_changes._length; ++i) {
    const auto& c = in.lockstep_changes._buffer[i];
    v.lockstep_changes.push_back({c.number, c.tick, from_c_str(c.participant), c.dropped, from_c_str(c.reason)});
  }
  return v;
}

void DdsType<msg::DoorCommand>::to_c(const msg::DoorCommand& v, C& out, Arena&) {
  out.door_id = c_str(v.door_id);
  out.angle = v.angle;
  out.source = c_str(v.source);
}

msg::DoorCommand DdsType<msg::DoorCommand>::from_c(const C& in) {
  return {from_c_str(in.door_id), in.angle, from_c_str(in.source)};
}

}  // namespace autonomy::dds
