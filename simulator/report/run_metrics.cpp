#include "simulator/report/run_metrics.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

namespace autonomy::sim {

namespace {

constexpr double kEdgeToleranceM = 1e-9;

double percent(double part, double whole) { return whole > 0.0 ? 100.0 * part / whole : 0.0; }

}  // namespace

CoverageGrid::CoverageGrid(const CoverageSettings& settings) : settings_(settings) {
  if (!settings.area.valid()) throw std::invalid_argument("coverage area is empty or inverted");
  if (!(settings.cell_size_m > 0.0) || !std::isfinite(settings.cell_size_m))
    throw std::invalid_argument("coverage cell size must be > 0");
  if (!(settings.sensor_square_m > 0.0) || !std::isfinite(settings.sensor_square_m))
    throw std::invalid_argument("coverage sensor square must be > 0");
  const double w = settings.area.max_x - settings.area.min_x, h = settings.area.max_y - settings.area.min_y;
  columns_ = std::max(1, static_cast<int>(std::ceil(w / settings.cell_size_m - 1e-9)));
  rows_ = std::max(1, static_cast<int>(std::ceil(h / settings.cell_size_m - 1e-9)));
}

geometry::Vec2 CoverageGrid::centre(int column, int row) const {
  return {settings_.area.min_x + (column + 0.5) * settings_.cell_size_m,
          settings_.area.min_y + (row + 0.5) * settings_.cell_size_m};
}

void CoverageGrid::for_each_sensed(const geometry::Vec2& p,
                                   const std::function<void(int, int)>& visit) const {
  const double half = 0.5 * settings_.sensor_square_m, res = settings_.cell_size_m;
  // Centre of cell k is min + (k + 0.5) res; keep those within [p - half, p + half].
  auto first = [&](double lo, double min) {
    return std::max(0.0, std::ceil((lo - kEdgeToleranceM - min) / res - 0.5));
  };
  auto last = [&](double hi, double min, int count) {
    return std::min(count - 1.0, std::floor((hi + kEdgeToleranceM - min) / res - 0.5));
  };
  const double c0 = first(p.x() - half, settings_.area.min_x), c1 = last(p.x() + half, settings_.area.min_x, columns_);
  const double r0 = first(p.y() - half, settings_.area.min_y), r1 = last(p.y() + half, settings_.area.min_y, rows_);
  for (double r = r0; r <= r1; ++r)
    for (double c = c0; c <= c1; ++c) visit(static_cast<int>(c), static_cast<int>(r));
}

RunMetrics::RunMetrics(CoverageSettings coverage, LineOfSight line_of_sight)
    : grid_(coverage), line_of_sight_(std::move(line_of_sight)),
      team_covered_(static_cast<size_t>(grid_.cells()), false) {}

void RunMetrics::sense(Robot& robot, const geometry::Vec2& position) {
  grid_.for_each_sensed(position, [&](int c, int r) {
    const size_t index = static_cast<size_t>(r) * grid_.columns() + c;
    if (robot.covered[index]) return;  // a covered cell stays covered: no sight test again
    if (line_of_sight_ && !line_of_sight_(position, grid_.centre(c, r))) return;
    robot.covered[index] = true;
    ++robot.m.cells_covered;
    if (!team_covered_[index]) {
      team_covered_[index] = true;
      ++team_cells_;
    }
  });
}

void RunMetrics::add(const TickSample& sample) {
  const double dt = sample.dt_s;
  run_time_s_ += dt;
  ++steps_;
  if (sample.team_fully_connected) fully_connected_s_ += dt;
  for (const RobotTickSample& s : sample.robots) {
    auto [it, is_new] = robots_.try_emplace(s.id);
    Robot& robot = it->second;
    if (is_new) {
      robot.m.id = s.id;
      robot.last_position = s.position;
      robot.covered.assign(team_covered_.size(), false);
    }
    if (is_new || !robot.m.finished) robot.m.mission_time_s += dt;
    robot.m.distance_m += (s.position - robot.last_position).norm();
    robot.m.present_time_s += dt;
    if (s.connected_to_teammate) robot.m.time_connected_s += dt;
    robot.m.finished = s.finished;
    robot.last_position = s.position;
    sense(robot, s.position);
  }
}

RunMetricsReport RunMetrics::report() const {
  RunMetricsReport out;
  out.coverage = grid_.settings();
  const double cell_area = grid_.settings().cell_size_m * grid_.settings().cell_size_m;
  TeamMetrics& team = out.team;
  team.run_time_s = run_time_s_;
  team.steps = steps_;
  team.time_fully_connected_s = fully_connected_s_;
  team.percent_time_fully_connected = percent(fully_connected_s_, run_time_s_);
  team.cells_total = grid_.cells();
  team.cells_covered = team_cells_;
  team.area_covered_m2 = static_cast<double>(team_cells_) * cell_area;
  team.percent_covered = percent(static_cast<double>(team_cells_), static_cast<double>(grid_.cells()));
  team.all_finished = !robots_.empty();
  for (const auto& [id, robot] : robots_) {
    RobotMetrics m = robot.m;
    m.percent_time_connected = percent(m.time_connected_s, m.present_time_s);
    m.area_covered_m2 = static_cast<double>(m.cells_covered) * cell_area;
    team.mission_time_s = std::max(team.mission_time_s, m.mission_time_s);
    team.distance_m += m.distance_m;
    team.all_finished = team.all_finished && m.finished;
    out.robots.push_back(m);
  }
  return out;
}

namespace {

std::string num(double v) {
  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(10);
  out << v;
  return out.str();
}

}  // namespace

std::string metrics_csv(const RunMetricsReport& r) {
  std::ostringstream csv;
  csv << "robot,mission_time_s,distance_m,time_connected_s,percent_time_connected,cells_covered,"
         "area_covered_m2,finished\n";
  for (const RobotMetrics& m : r.robots)
    csv << m.id << ',' << num(m.mission_time_s) << ',' << num(m.distance_m) << ',' << num(m.time_connected_s) << ','
        << num(m.percent_time_connected) << ',' << m.cells_covered << ',' << num(m.area_covered_m2) << ','
        << (m.finished ? "true" : "false") << '\n';
  const TeamMetrics& t = r.team;
  csv << "team," << num(t.mission_time_s) << ',' << num(t.distance_m) << ',' << num(t.time_fully_connected_s) << ','
      << num(t.percent_time_fully_connected) << ',' << t.cells_covered << ',' << num(t.area_covered_m2) << ','
      << (t.all_finished ? "true" : "false") << '\n';
  return csv.str();
}

std::string metrics_json(const RunMetricsReport& r) {
  nlohmann::ordered_json j;
  j["coverage"] = {{"area", {r.coverage.area.min_x, r.coverage.area.min_y, r.coverage.area.max_x,
                             r.coverage.area.max_y}},
                   {"cell_size_m", r.coverage.cell_size_m},
                   {"sensor_square_m", r.coverage.sensor_square_m},
                   {"cells_total", r.team.cells_total}};
  const TeamMetrics& t = r.team;
  j["team"] = {{"run_time_s", t.run_time_s},
               {"steps", t.steps},
               {"mission_time_s", t.mission_time_s},
               {"distance_m", t.distance_m},
               {"time_fully_connected_s", t.time_fully_connected_s},
               {"percent_time_fully_connected", t.percent_time_fully_connected},
               {"cells_covered", t.cells_covered},
               {"area_covered_m2", t.area_covered_m2},
               {"percent_covered", t.percent_covered},
               {"all_finished", t.all_finished}};
  j["robots"] = nlohmann::ordered_json::array();
  for (const RobotMetrics& m : r.robots)
    j["robots"].push_back({{"id", m.id},
                           {"mission_time_s", m.mission_time_s},
                           {"distance_m", m.distance_m},
                           {"time_connected_s", m.time_connected_s},
                           {"present_time_s", m.present_time_s},
                           {"percent_time_connected", m.percent_time_connected},
                           {"cells_covered", m.cells_covered},
                           {"area_covered_m2", m.area_covered_m2},
                           {"finished", m.finished}});
  return j.dump(2) + "\n";
}

}  // namespace autonomy::sim
