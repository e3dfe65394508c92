#include "services/viewer/core/frames.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace autonomy::viewer {

namespace {

using nlohmann::json;

double viewer_mm(double metres) { return std::round(metres * 1000.0) / 1000.0; }

json robot_json(const RobotView& r) {
  const msg::RobotState& s = r.state;
  json trail = json::array();
  for (const TrailPoint& p : r.trail) {
    trail.push_back(viewer_mm(p.x));
    trail.push_back(viewer_mm(p.y));
  }
  json out = {{"id", s.robot_id},
              {"x", viewer_mm(s.x)},
              {"y", viewer_mm(s.y)},
              {"theta", viewer_mm(s.theta)},
              {"radius", viewer_mm(s.radius)},
              {"vx", viewer_mm(s.vx)},
              {"vy", viewer_mm(s.vy)},
              {"omega", viewer_mm(s.omega)},
              {"kinematics", msg::to_string(s.kinematics)},
              {"collision", s.in_collision},
              {"tick", s.tick},
              {"trail", std::move(trail)}};
  if (r.goal) {
    const GoalView& g = *r.goal;
    json goal = {{"id", g.goal_id}};
    if (g.has_position) {
      goal["x"] = viewer_mm(g.x);
      goal["y"] = viewer_mm(g.y);
    }
    if (g.has_status) {
      goal["state"] = msg::to_string(g.state);
      goal["reason"] = g.reason;
      goal["distance"] = viewer_mm(g.distance_to_goal);
    }
    out["goal"] = std::move(goal);
  }
  if (r.itinerary) {
    const msg::Itinerary& it = *r.itinerary;
    json path = json::array();
    for (const msg::ItineraryPoint& p : it.path) {
      path.push_back(viewer_mm(p.x));
      path.push_back(viewer_mm(p.y));
    }
    out["itinerary"] = {{"path", std::move(path)},
                        {"passage", it.passage},
                        {"claim", it.claim},
                        {"waiting_for", it.waiting_for}};
  }
  return out;
}

const msg::MapDoor* find_map_door(const WorldView& view, const std::string& id) {
  if (!view.map()) return nullptr;
  for (const msg::MapDoor& d : view.map()->doors)
    if (d.id == id) return &d;
  return nullptr;
}

json door_json(const WorldView& view, const msg::DoorState& d) {
  json out = {{"id", d.door_id},
              {"angle", viewer_mm(d.angle)},
              {"target", viewer_mm(d.target_angle)},
              {"closed", d.closed},
              {"blocked", d.blocked}};
  if (const msg::MapDoor* spec = find_map_door(view, d.door_id)) {
    const LeafSegment leaf = door_leaf(*spec, d.angle);
    out["leaf"] = {viewer_mm(leaf.hinge_x), viewer_mm(leaf.hinge_y), viewer_mm(leaf.tip_x), viewer_mm(leaf.tip_y)};
  }
  return out;
}

json job_json(const JobView& v) {
  const msg::CourierJobStatus& j = v.latest;
  json history = json::array();
  for (const JobStateChange& c : v.history)
    history.push_back({{"state", msg::to_string(c.state)}, {"phase", c.phase}, {"tick", c.tick}});
  return {{"id", j.job_id},
          {"state", msg::to_string(j.state)},
          {"phase", j.phase},
          {"robot", j.robot_id},
          {"object", j.object_id},
          {"from", j.from},
          {"to", j.to},
          {"deadline", j.deadline},
          {"eta", j.estimated_completion},
          {"reason", j.reason},
          {"allocation", j.allocation},
          {"tick", j.tick},
          {"order", v.first_seen},
          {"history", std::move(history)}};
}


double viewer_seconds(int64_t ns) { return viewer_mm(static_cast<double>(ns) * 1e-9); }

// A plan's bound in simulated seconds; null when it has none (magnitude >= 2^52).
json plan_bound(int64_t origin_s, int64_t bound) {
  if (bound >= (int64_t{1} << 52) || bound <= -(int64_t{1} << 52)) return nullptr;
  return origin_s + bound;
}

json executed_plan_json(const std::string& id, const ExecutiveTrace& trace) {
  const auto found = trace.plans.find(id);
  if (found == trace.plans.end()) return {{"id", id}, {"known", false}};  // ran, but not heard
  const msg::LatestPlan& p = found->second;
  const int64_t origin = p.plan_origin;
  json timelines = json::array();
  for (const msg::PlanTimeline& line : p.plan.timelines) {
    json tokens = json::array();
    for (uint32_t i : line.tokens) {
      if (i >= p.plan.tokens.size()) continue;  // checked by the executive; never drawn wrong
      const msg::PlanToken& t = p.plan.tokens[i];
      tokens.push_back({{"id", t.id},
                        {"predicate", t.predicate},
                        {"parameters", t.parameters},
                        {"start", {plan_bound(origin, t.start_lb), plan_bound(origin, t.start_ub)}},
                        {"end", {plan_bound(origin, t.end_lb), plan_bound(origin, t.end_ub)}}});
    }
    timelines.push_back({{"name", line.name}, {"tokens", std::move(tokens)}});
  }
  return {{"id", id},
          {"known", true},
          {"origin_s", origin},
          {"horizon_s", plan_bound(origin, p.plan.horizon)},
          {"timelines", std::move(timelines)}};
}

json executive_trace_json(const ExecutiveTrace& trace, std::size_t plans) {
  // The plans it ran last; before it runs one, the latest it was given.
  std::vector<std::string> shown(trace.plan_order.end() - std::min(plans, trace.plan_order.size()),
                                 trace.plan_order.end());
  if (shown.empty() && !trace.plans_heard.empty()) shown.push_back(trace.plans_heard.back());
  const std::set<std::string> shown_set(shown.begin(), shown.end());
  json plan_list = json::array();
  for (const std::string& id : shown) plan_list.push_back(executed_plan_json(id, trace));
  json executed = json::array();
  std::optional<int64_t> since;  // the earliest time drawn: marks before it are not sent
  for (const ExecutedToken& t : trace.tokens) {
    if (!shown_set.count(t.plan_id)) continue;
    const auto first = t.start_ns ? t.start_ns : t.end_ns;
    if (first) since = since ? std::min(*since, *first) : *first;
    executed.push_back({{"plan", t.plan_id},
                        {"token", t.token},
                        {"timeline", t.timeline},
                        {"value", t.value},
                        {"start_s", t.start_ns ? json(viewer_seconds(*t.start_ns)) : json(nullptr)},
                        {"end_s", t.end_ns ? json(viewer_seconds(*t.end_ns)) : json(nullptr)},
                        {"cut", t.cut}});
  }
  for (const auto& p : plan_list)
    if (p.contains("origin_s")) {
      const int64_t origin_ns = p["origin_s"].get<int64_t>() * 1000000000LL;
      since = since ? std::min(*since, origin_ns) : origin_ns;
    }
  json marks = json::array();
  constexpr std::size_t kMarksSent = 100;
  for (auto it = trace.marks.rbegin(); it != trace.marks.rend() && marks.size() < kMarksSent; ++it) {
    if (since && it->sim_time_ns < *since) break;
    marks.push_back({{"t_s", viewer_seconds(it->sim_time_ns)},
                     {"tick", it->tick},
                     {"kind", it->kind},
                     {"text", it->text},
                     {"plan", it->plan_id}});
  }
  std::reverse(marks.begin(), marks.end());
  return {{"plan_id", trace.plan_id},
          {"latest_s", viewer_seconds(trace.latest_ns)},
          {"lost", trace.lost},
          {"refused", trace.refused},
          {"plans", std::move(plan_list)},
          {"executed", std::move(executed)},
          {"marks", std::move(marks)}};
}

}  // namespace

LeafSegment door_leaf(const msg::MapDoor& door, double angle) {
  const double hinge_x = door.x - 0.5 * door.width * std::cos(door.heading);
  const double hinge_y = door.y - 0.5 * door.width * std::sin(door.heading);
  const double turn = door.open_angle < 0.0 ? -angle : angle;
  return {hinge_x, hinge_y, hinge_x + door.width * std::cos(door.heading + turn),
          hinge_y + door.width * std::sin(door.heading + turn)};
}

std::vector<uint32_t> raster_runs(const msg::MapRaster& raster) {
  std::vector<uint32_t> runs;
  uint8_t current = 0;
  uint32_t length = 0;
  for (uint8_t cell : raster.blocked) {
    const uint8_t blocked = cell != 0 ? 1 : 0;
    if (blocked != current) {
      runs.push_back(length);
      current = blocked;
      length = 0;
    }
    ++length;
  }
  runs.push_back(length);
  return runs;
}

nlohmann::json map_frame(const WorldView& view) {
  json out = {{"type", "map"}};
  if (!view.map()) {
    out["known"] = false;
    return out;
  }
  const msg::WorldMap& m = *view.map();
  out["known"] = true;
  out["name"] = m.name;
  out["width"] = m.width;
  out["height"] = m.height;
  json obstacles = json::array();
  for (const auto& r : m.obstacles)
    obstacles.push_back({viewer_mm(r.min_x), viewer_mm(r.min_y), viewer_mm(r.max_x), viewer_mm(r.max_y)});
  out["obstacles"] = std::move(obstacles);
  json polygons = json::array();
  for (const msg::MapPolygon& p : m.polygons) {
    json points = json::array();
    for (const msg::MapPoint& v : p.vertices) {
      points.push_back(viewer_mm(v.x));
      points.push_back(viewer_mm(v.y));
    }
    polygons.push_back({{"name", p.name}, {"points", std::move(points)}});
  }
  out["polygons"] = std::move(polygons);
  json rasters = json::array();
  for (const msg::MapRaster& r : m.rasters) {
    rasters.push_back({{"name", r.name},
                       {"origin_x", r.origin_x},
                       {"origin_y", r.origin_y},
                       {"resolution", r.resolution},
                       {"cols", r.cols},
                       {"rows", r.rows},
                       {"runs", raster_runs(r)}});
  }
  out["rasters"] = std::move(rasters);
  json doors = json::array();
  for (const msg::MapDoor& d : m.doors) {
    doors.push_back({{"id", d.id},
                     {"x", viewer_mm(d.x)},
                     {"y", viewer_mm(d.y)},
                     {"width", viewer_mm(d.width)},
                     {"heading", d.heading},
                     {"open_angle", d.open_angle}});
  }
  out["doors"] = std::move(doors);
  return out;
}

nlohmann::json state_frame(const WorldView& view, uint64_t sequence) {
  json robots = json::array();
  // A robot known only by its goal or itinerary (its state not heard yet) has no place to be drawn.
  for (const auto& [id, r] : view.robots())
    if (r.has_state) robots.push_back(robot_json(r));
  json doors = json::array();
  for (const auto& [id, d] : view.doors()) doors.push_back(door_json(view, d));
  json links = json::array();
  for (const auto& [key, l] : view.links()) {
    links.push_back({{"a", l.robot_a},
                     {"b", l.robot_b},
                     {"signal_dbm", viewer_mm(l.signal_dbm)},
                     {"margin_db", viewer_mm(l.margin_db)},
                     {"connected", l.connected}});
  }
  json jobs = json::array();
  for (const auto& [id, j] : view.jobs()) jobs.push_back(job_json(j));
  return {{"type", "state"},
          {"seq", sequence},
          {"tick", view.tick()},
          {"sim_time_s", viewer_mm(static_cast<double>(view.sim_time_ns()) * 1e-9)},
          {"robots", std::move(robots)},
          {"doors", std::move(doors)},
          {"links", std::move(links)},
          {"jobs", std::move(jobs)}};
}

nlohmann::json execution_frame(const ExecutionTraces& traces, std::size_t plans) {
  json executives = json::object();
  for (const auto& [name, trace] : traces.executives()) {
    // A requester of plans that never told what it did is no executive to draw.
    if (trace.last_number == 0 && trace.tokens.empty() && trace.marks.empty()) continue;
    executives[name] = executive_trace_json(trace, plans);
  }
  return {{"type", "execution"}, {"executives", std::move(executives)}};
}

}  // namespace autonomy::viewer
