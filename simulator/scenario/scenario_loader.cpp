#include "simulator/scenario/scenario_loader.hpp"

#include "idl/scenario.pb.h"
#include "simulator/core/free_space.hpp"
#include "simulator/core/number_format.hpp"
#include "simulator/core/robot_id.hpp"
#include "simulator/core/shapes.hpp"
#include "simulator/office/office_spec.hpp"
#include "simulator/office/time_of_day.hpp"
#include "simulator/scenario/spacecraft_section.hpp"

#include "common/config/text_format.hpp"
#include "common/grid/map_loader.hpp"

#include <google/protobuf/text_format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <tuple>

namespace autonomy::sim {

namespace {

namespace pb = google::protobuf;
using ParseInfoTree = pb::TextFormat::ParseInfoTree;

using configfile::Locator;
using configfile::Position;

std::string point_text(double x, double y) {
  return "(" + format_number(x) + ", " + format_number(y) + ")";
}

bool all_finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

// Checks a parsed scenario and converts it to plain structs, collecting every problem.
class ScenarioChecker {
 public:
  ScenarioChecker(const std::string& source, std::vector<ScenarioError>& errors)
      : source_(source), errors_(errors) {
    const std::size_t slash = source.find_last_of('/');
    base_dir_ = slash == std::string::npos ? "" : source.substr(0, slash + 1);
  }

  Scenario check(const config::Scenario& file, const ParseInfoTree& tree) {
    const Locator root(&tree, config::Scenario::descriptor(), Position{});
    Scenario out;
    out.world.name = file.name();
    world(file, root, out.world);
    rooms(file, root, out);
    doors(file, root, out.world);
    out.world.attach_defaults = attach_defaults(file.attach_defaults(), root.nested("attach_defaults"));
    robots(file, root, out.world);
    places(file, root, out);
    waypoints(file, root, out);
    parking(file, root, out);
    radio(file, root, out);
    office(file, root, out);
    if (file.has_spacecraft())
      out.spacecraft = check_spacecraft_section(file.spacecraft(), root.nested("spacecraft"), source_, errors_);
    simulation(file.simulation(), root.nested("simulation"), out);
    out.world.seed = out.simulation.seed;
    return out;
  }

 private:
  void error(Position at, std::string message) {
    errors_.push_back({source_, at.line, at.column, std::move(message)});
  }

  // An explicit value must be a positive finite number; an absent one takes `fallback`.
  double positive(bool present, double value, double fallback, const std::string& what,
                  Position at) {
    if (!present) return fallback;
    if (!(std::isfinite(value) && value > 0.0)) {
      error(at, what + " must be positive (got " + format_number(value) + ")");
    }
    return value;
  }

  void world(const config::Scenario& file, const Locator& root, WorldSpec& out) {
    if (!file.has_world() && !file.has_spacecraft()) {
      error(root.self(), "world is missing");
      return;
    }
    // A spacecraft scenario needs no robot world: an empty square stands in for it.
    config::World placeholder;
    placeholder.set_width(1.0);
    placeholder.set_height(1.0);
    const config::World& w = file.has_world() ? file.world() : placeholder;
    const Locator at = root.nested("world");
    out.width = positive(true, w.width(), 0.0, "world: width", at.at("width"));
    out.height = positive(true, w.height(), 0.0, "world: height", at.at("height"));
    world_valid_ = std::isfinite(out.width) && out.width > 0.0 && std::isfinite(out.height) &&
                   out.height > 0.0;
    for (int i = 0; i < w.obstacles_size(); ++i) {
      const config::Rectangle& r = w.obstacles(i);
      const geometry::Rect rect{r.min_x(), r.min_y(), r.max_x(), r.max_y()};
      const Position where = at.at("obstacles", i);
      const std::string name = "obstacle " + std::to_string(i);
      if (!all_finite({rect.min_x, rect.min_y, rect.max_x, rect.max_y})) {
        error(where, name + " has a coordinate that is not finite");
      } else if (!rect.valid()) {
        error(where, name + " is empty or inverted: min " + point_text(rect.min_x, rect.min_y) +
                         " must be below max " + point_text(rect.max_x, rect.max_y));
      } else if (world_valid_ && (rect.min_x < 0.0 || rect.min_y < 0.0 ||
                                  rect.max_x > out.width || rect.max_y > out.height)) {
        error(where, name + " from " + point_text(rect.min_x, rect.min_y) + " to " +
                         point_text(rect.max_x, rect.max_y) + " extends outside the world " +
                         world_text(out));
      }
      // Invalid obstacles are kept out of the robot checks, so one typo gives one error.
      if (rect.valid() && all_finite({rect.min_x, rect.min_y, rect.max_x, rect.max_y})) {
        checked_obstacles_.emplace_back(i, rect);
      }
      out.obstacles.push_back(rect);
    }
    for (int i = 0; i < w.polygons_size(); ++i) {
      const config::Polygon& p = w.polygons(i);
      const std::string name = "polygon " + std::to_string(i) + (p.name().empty() ? "" : " '" + p.name() + "'");
      std::vector<geometry::Vec2> vertices = points(p.vertices());
      if (vertices_ok(vertices, name, at.at("polygons", i), out)) {
        checked_polygon_index_.push_back(i);
        out.polygons.push_back({p.name(), std::move(vertices)});
      }
    }
    for (int i = 0; i < w.maps_size(); ++i) {
      const Position where = at.nested("maps", i).at("yaml");
      const std::string& yaml = w.maps(i).yaml();
      if (yaml.empty()) {
        error(at.at("maps", i), "map " + std::to_string(i) + ": yaml is missing");
        continue;
      }
      const std::string path = !yaml.empty() && yaml[0] == '/' ? yaml : base_dir_ + yaml;
      grid::MapLoadResult loaded = grid::load_ros_map(path);
      if (!loaded.ok()) {
        error(where, "map '" + yaml + "': " + loaded.error);
        continue;
      }
      if (loaded.map->raster.origin().yaw != 0.0) {
        error(where, "map '" + yaml + "': origin yaw must be 0 (got " +
                         format_number(loaded.map->raster.origin().yaw) + ")");
        continue;
      }
      out.rasters.push_back(
          {yaml, std::make_shared<const grid::OccupancyRaster>(std::move(loaded.map->raster))});
    }
    if (world_valid_) {
      // Rectangles are checked one by one above (their messages name the file index); the
      // polygons and maps that passed go into a map for the placement checks.
      obstacle_map_ = std::make_unique<ObstacleMap>(out.width, out.height, std::vector<geometry::Rect>{},
                                                    out.polygons, out.rasters);
    }
  }

  template <typename Points>
  static std::vector<geometry::Vec2> points(const Points& list) {
    std::vector<geometry::Vec2> out;
    for (const config::Point& p : list) out.emplace_back(p.x(), p.y());
    return out;
  }

  // A usable polygon inside the world; reports the first problem.
  bool vertices_ok(const std::vector<geometry::Vec2>& vertices, const std::string& name, Position where,
                   const WorldSpec& world) {
    if (const auto problem = polygon_problem(vertices)) {
      error(where, name + " " + *problem);
      return false;
    }
    for (std::size_t k = 0; k < vertices.size(); ++k) {
      if (world_valid_ && !inside_world(vertices[k], world)) {
        error(where, name + ": vertex " + std::to_string(k) + " " + point_text(vertices[k].x(), vertices[k].y()) +
                         " is outside the world " + world_text(world));
        return false;
      }
    }
    return true;
  }

  static bool inside_world(const geometry::Vec2& p, const WorldSpec& w) {
    return p.x() >= 0.0 && p.y() >= 0.0 && p.x() <= w.width && p.y() <= w.height;
  }

  // Why a point cannot be stood on (outside the world, inside an obstacle), if it cannot.
  std::optional<std::string> point_problem(const geometry::Vec2& p, const WorldSpec& world) const {
    if (!all_finite({p.x(), p.y()})) return std::string("is not finite");
    if (!world_valid_) return std::nullopt;
    if (!inside_world(p, world)) return "is outside the world " + world_text(world);
    for (const auto& [index, rect] : checked_obstacles_) {
      if (geometry::distance(rect, p) < 1e-9) return "is inside obstacle " + std::to_string(index);
    }
    if (const auto hit = obstacle_map_->overlap(p, 1e-9)) return "is inside " + obstacle_text(*hit);
    return std::nullopt;
  }

  // An obstacle of obstacle_map_ named by its position in the file.
  std::string obstacle_text(const ObstacleRef& ref) const {
    if (ref.kind != ObstacleRef::Kind::Polygon) return obstacle_map_->describe(ref);
    ObstacleRef in_file = ref;
    in_file.index = static_cast<std::size_t>(checked_polygon_index_.at(ref.index));
    const std::string text = obstacle_map_->describe(ref);  // "polygon k 'name'"
    return "polygon " + std::to_string(in_file.index) + text.substr(text.find(' ', 8));
  }

  // A valid name: unique among `seen`; reports problems at `where`.
  bool unique_name(const std::string& what, const std::string& name, Position where,
                   std::map<std::string, int>& seen) {
    if (name.empty()) {
      error(where, what + " name is empty");
      return false;
    }
    if (const auto [it, fresh] = seen.emplace(name, where.line); !fresh) {
      error(where, "duplicate " + what + " '" + name + "' (first defined at line " + std::to_string(it->second) + ")");
      return false;
    }
    return true;
  }

  void rooms(const config::Scenario& file, const Locator& root, Scenario& out) {
    for (int i = 0; i < file.rooms_size(); ++i) {
      const config::Room& r = file.rooms(i);
      const Locator at = root.nested("rooms", i);
      if (!unique_name("room", r.name(), at.at("name"), room_lines_)) continue;
      RoomSpec room{r.name(), r.kind(), std::nullopt};
      if (r.has_bounds()) {
        const config::Rectangle& b = r.bounds();
        const geometry::Rect rect{b.min_x(), b.min_y(), b.max_x(), b.max_y()};
        if (!all_finite({rect.min_x, rect.min_y, rect.max_x, rect.max_y}) || !rect.valid()) {
          error(at.at("bounds"), "room '" + r.name() + "': bounds are empty, inverted or not finite");
        } else {
          room.bounds = rect;
        }
      }
      out.rooms.push_back(std::move(room));
    }
  }

  bool known_room(const std::string& who, const std::string& room, Position where) {
    if (room_lines_.count(room) != 0) return true;
    error(where, who + ": unknown room '" + room + "'");
    return false;
  }

  void doors(const config::Scenario& file, const Locator& root, WorldSpec& world) {
    std::map<std::string, int> first_line;
    for (int i = 0; i < file.doors_size(); ++i) {
      const config::Door& d = file.doors(i);
      const Locator at = root.nested("doors", i);
      const std::string who = "door " + (d.id().empty() ? "#" + std::to_string(i) : d.id());
      bool ok = true;
      if (const auto problem = robot_id_problem(d.id())) {
        std::string text = *problem;
        text.replace(0, 5, "door");  // "robot id ..." -> "door id ..."
        error(at.at("id"), text);
        ok = false;
      } else if (const auto [it, fresh] = first_line.emplace(d.id(), at.at("id").line); !fresh) {
        error(at.at("id"), "duplicate door id " + d.id() + " (first defined at line " + std::to_string(it->second) + ")");
        ok = false;
      }
      DoorSpec door;
      door.id = d.id();
      if (!d.has_position()) {
        error(at.self(), who + ": position is missing");
        ok = false;
      }
      door.position = {d.position().x(), d.position().y()};
      door.width = d.width();
      door.heading = d.heading();
      door.swing = d.swing() == config::CLOCKWISE ? DoorSwing::Clockwise : DoorSwing::CounterClockwise;
      door.max_angle = d.has_max_angle() ? d.max_angle() : M_PI / 2;
      door.angle = d.has_angle() ? d.angle() : door.max_angle;
      if (d.rooms_size() != 2) {
        error(at.self(), who + ": rooms must name exactly 2 rooms (got " + std::to_string(d.rooms_size()) + ")");
        ok = false;
      }
      for (int k = 0; k < d.rooms_size() && k < 2; ++k) {
        ok = known_room(who, d.rooms(k), at.at("rooms", k)) && ok;
        door.rooms[static_cast<std::size_t>(k)] = d.rooms(k);
      }
      if (const auto problem = door_problem(door)) {
        const char* field = !(std::isfinite(door.width) && door.width > 0.0) ? "width"
                            : !(door.max_angle > 0.0 && door.max_angle <= M_PI) ? "max_angle"
                                                                                 : "angle";
        error(at.at(field), who + ": " + *problem);
        ok = false;
      } else if (world_valid_) {
        const DoorLeaf closed = door.leaf(0.0);
        for (const geometry::Vec2& end : {closed.hinge, closed.tip}) {
          if (!inside_world(end, world)) {
            error(at.at("position"), who + ": doorway end " + point_text(end.x(), end.y()) +
                                         " is outside the world " + world_text(world));
            ok = false;
            break;
          }
        }
      }
      if (d.has_script()) {
        door.schedule.kind = DoorScheduleSpec::Kind::Script;
        const Locator script = at.nested("script");
        double last = 0.0;
        for (int k = 0; k < d.script().events_size(); ++k) {
          const config::DoorEvent& e = d.script().events(k);
          const Position where = script.at("events", k);
          if (!(std::isfinite(e.time_s()) && e.time_s() >= 0.0)) {
            error(where, who + ": event time " + format_number(e.time_s()) + " must be >= 0");
            ok = false;
          } else if (e.time_s() < last) {
            error(where, who + ": event time " + format_number(e.time_s()) + " is before the previous event's " +
                             format_number(last));
            ok = false;
          }
          last = std::max(last, e.time_s());
          if (!(e.angle() >= 0.0 && e.angle() <= door.max_angle)) {
            error(where, who + ": event angle " + format_number(e.angle()) + " is outside [0, " +
                             format_number(door.max_angle) + "]");
            ok = false;
          }
          door.schedule.script.push_back({e.time_s(), e.angle()});
        }
      } else if (d.has_random()) {
        door.schedule.kind = DoorScheduleSpec::Kind::Random;
        const config::DoorRandom& r = d.random();
        const Locator rl = at.nested("random");
        for (const auto& [name, value] : {std::pair<const char*, double>{"close_rate_hz", r.close_rate_hz()},
                                          std::pair<const char*, double>{"open_rate_hz", r.open_rate_hz()}}) {
          if (!(std::isfinite(value) && value >= 0.0)) {
            error(rl.at(name), who + ": " + name + " must be >= 0 (got " + format_number(value) + ")");
            ok = false;
          }
        }
        door.schedule.random = {r.close_rate_hz(), r.open_rate_hz(),
                                r.has_open_angle() ? r.open_angle() : door.max_angle};
        if (!(door.schedule.random.open_angle > 0.0 && door.schedule.random.open_angle <= door.max_angle)) {
          error(rl.at("open_angle"), who + ": open_angle " + format_number(door.schedule.random.open_angle) +
                                         " is outside (0, " + format_number(door.max_angle) + "]");
          ok = false;
        }
      }
      if (ok) world.doors.push_back(std::move(door));
    }
  }

  void places(const config::Scenario& file, const Locator& root, Scenario& out) {
    std::map<std::string, int> seen;
    std::map<std::string, const RoomSpec*> rooms;
    for (const RoomSpec& r : out.rooms) rooms[r.name] = &r;
    for (int i = 0; i < file.places_size(); ++i) {
      const config::Place& p = file.places(i);
      const Locator at = root.nested("places", i);
      if (!unique_name("place", p.name(), at.at("name"), seen)) continue;
      const std::string who = "place '" + p.name() + "'";
      bool ok = known_room(who, p.room(), at.at("room"));
      if (!p.has_position()) {
        error(at.self(), who + ": position is missing");
        continue;
      }
      const geometry::Vec2 position{p.position().x(), p.position().y()};
      if (const auto problem = point_problem(position, out.world)) {
        error(at.at("position"), who + " at " + point_text(position.x(), position.y()) + " " + *problem);
        ok = false;
      } else if (ok && rooms.count(p.room()) != 0 && rooms[p.room()]->bounds &&
                 !rooms[p.room()]->bounds->contains(position)) {
        error(at.at("position"), who + " at " + point_text(position.x(), position.y()) +
                                     " is outside the bounds of room '" + p.room() + "'");
        ok = false;
      }
      office::Place place{p.name(), office::PlaceKind::desk, p.room(), position, 1.0};
      switch (p.kind()) {
        case config::PLACE_KIND_UNSPECIFIED:
        case config::DESK: place.kind = office::PlaceKind::desk; break;
        case config::TABLE: place.kind = office::PlaceKind::table; break;
        case config::STATION: place.kind = office::PlaceKind::station; break;
        default:
          error(at.at("kind"), who + ": unknown kind value " + std::to_string(static_cast<int>(p.kind())));
          ok = false;
      }
      place.radius = positive(p.has_radius(), p.radius(), 1.0, who + ": radius", at.at("radius"));
      ok = ok && std::isfinite(place.radius) && place.radius > 0.0;
      if (ok) {
        out.places.push_back({p.name(), p.room(), position});
        office_places_.push_back({std::move(place), at.at("name")});
      }
    }
  }

  void waypoints(const config::Scenario& file, const Locator& root, Scenario& out) {
    std::map<std::string, int> seen;
    for (int i = 0; i < file.waypoints_size(); ++i) {
      const config::Waypoint& w = file.waypoints(i);
      const Locator at = root.nested("waypoints", i);
      if (!unique_name("waypoint", w.name(), at.at("name"), seen)) continue;
      if (!w.has_position()) {
        error(at.self(), "waypoint '" + w.name() + "': position is missing");
        continue;
      }
      const geometry::Vec2 position{w.position().x(), w.position().y()};
      if (!all_finite({position.x(), position.y()}) || (world_valid_ && !inside_world(position, out.world))) {
        error(at.at("position"), "waypoint '" + w.name() + "' at " + point_text(position.x(), position.y()) +
                                     " is outside the world " + world_text(out.world));
        continue;
      }
      out.waypoints.push_back({w.name(), position});
    }
  }

  // Where a robot parks must be free space (a waypoint only inside the world): a spot in a wall
  // would send every idle courier of a fleet into it.
  void parking(const config::Scenario& file, const Locator& root, Scenario& out) {
    std::map<std::string, int> seen;
    for (int i = 0; i < file.parking_size(); ++i) {
      const config::Waypoint& w = file.parking(i);
      const Locator at = root.nested("parking", i);
      if (!unique_name("parking spot", w.name(), at.at("name"), seen)) continue;
      const std::string who = "parking spot '" + w.name() + "'";
      if (!w.has_position()) {
        error(at.self(), who + ": position is missing");
        continue;
      }
      const geometry::Vec2 position{w.position().x(), w.position().y()};
      if (const auto problem = point_problem(position, out.world)) {
        error(at.at("position"), who + " at " + point_text(position.x(), position.y()) + " " + *problem);
        continue;
      }
      out.parking.push_back({w.name(), position});
    }
  }

  void radio(const config::Scenario& file, const Locator& root, Scenario& scenario) {
    RadioSettings& out = scenario.radio;
    for (int i = 0; i < file.attenuating_areas_size(); ++i) {
      const config::AttenuatingArea& a = file.attenuating_areas(i);
      const Locator at = root.nested("attenuating_areas", i);
      const std::string name = "attenuating area " + std::to_string(i) + (a.name().empty() ? "" : " '" + a.name() + "'");
      std::vector<geometry::Vec2> vertices = points(a.vertices());
      bool ok = vertices_ok(vertices, name, at.self(), scenario.world);
      for (const auto& [field, value] : {std::pair<const char*, double>{"loss_db_per_m", a.loss_db_per_m()},
                                         std::pair<const char*, double>{"entry_loss_db", a.entry_loss_db()}}) {
        if (!(std::isfinite(value) && value >= 0.0)) {
          error(at.at(field), name + ": " + field + " must be >= 0 (got " + format_number(value) + ")");
          ok = false;
        }
      }
      if (ok) out.areas.push_back({a.name(), std::move(vertices), a.loss_db_per_m(), a.entry_loss_db()});
    }
    if (!file.has_radio()) return;
    const config::Radio& r = file.radio();
    const Locator at = root.nested("radio");
    enum class Rule { Any, Positive, NonNegative };
    const auto field = [&](bool present, double value, const char* name, Rule rule, std::optional<double>& to) {
      if (!present) return;
      const bool ok = std::isfinite(value) && (rule == Rule::Any || (rule == Rule::Positive && value > 0.0) ||
                                               (rule == Rule::NonNegative && value >= 0.0));
      if (!ok) {
        const char* need = rule == Rule::Positive ? "positive" : rule == Rule::NonNegative ? ">= 0" : "finite";
        error(at.at(name), std::string("radio: ") + name + " must be " + need + " (got " + format_number(value) + ")");
      }
      to = value;
    };
    field(r.has_tx_power_dbm(), r.tx_power_dbm(), "tx_power_dbm", Rule::Any, out.tx_power_dbm);
    field(r.has_frequency_hz(), r.frequency_hz(), "frequency_hz", Rule::Positive, out.frequency_hz);
    out.distance_model = r.distance_model() == config::ITU_P1238 ? RadioSettings::DistanceModel::ItuP1238
                                                                 : RadioSettings::DistanceModel::LogDistance;
    field(r.has_reference_distance_m(), r.reference_distance_m(), "reference_distance_m", Rule::Positive,
          out.reference_distance_m);
    field(r.has_reference_loss_db(), r.reference_loss_db(), "reference_loss_db", Rule::NonNegative,
          out.reference_loss_db);
    field(r.has_path_loss_exponent(), r.path_loss_exponent(), "path_loss_exponent", Rule::Positive,
          out.path_loss_exponent);
    field(r.has_p1238_power_loss_coefficient(), r.p1238_power_loss_coefficient(), "p1238_power_loss_coefficient",
          Rule::Positive, out.p1238_power_loss_coefficient);
    field(r.has_p1238_floor_penetration_db(), r.p1238_floor_penetration_db(), "p1238_floor_penetration_db",
          Rule::NonNegative, out.p1238_floor_penetration_db);
    field(r.has_receiver_sensitivity_dbm(), r.receiver_sensitivity_dbm(), "receiver_sensitivity_dbm", Rule::Any,
          out.receiver_sensitivity_dbm);
    field(r.has_wall_loss_db(), r.wall_loss_db(), "wall_loss_db", Rule::NonNegative, out.wall_loss_db);
    field(r.has_inside_loss_db_per_m(), r.inside_loss_db_per_m(), "inside_loss_db_per_m", Rule::NonNegative,
          out.inside_loss_db_per_m);
    field(r.has_good_margin_db(), r.good_margin_db(), "good_margin_db", Rule::Positive, out.good_margin_db);
    field(r.has_loss_exponent(), r.loss_exponent(), "loss_exponent", Rule::Positive, out.loss_exponent);
    field(r.has_base_delay_s(), r.base_delay_s(), "base_delay_s", Rule::NonNegative, out.base_delay_s);
    field(r.has_per_hop_delay_s(), r.per_hop_delay_s(), "per_hop_delay_s", Rule::NonNegative, out.per_hop_delay_s);
    field(r.has_weak_link_delay_s(), r.weak_link_delay_s(), "weak_link_delay_s", Rule::NonNegative,
          out.weak_link_delay_s);
    field(r.has_jitter_s(), r.jitter_s(), "jitter_s", Rule::NonNegative, out.jitter_s);
  }

  // --- Office: people, objects, loading stations (simulator/office) ---------------------------

  // The place named `name` among those that passed, or an error at `where` (a room named by
  // mistake gets a hint).
  const office::Place* office_place(const std::string& who, const std::string& name, Position where) {
    for (const auto& [p, at] : office_places_)
      if (p.name == name) return &p;
    std::string text = who + ": unknown place '" + name + "'";
    if (room_lines_.count(name) != 0) text += " (a room; name a place in it)";
    error(where, text);
    return nullptr;
  }

  // A handover time model; absent means 10 s.
  office::HandoverTimeModel handover_time(bool present, const config::HandoverTime& t, const std::string& who,
                                          const Locator& at) {
    if (!present) return office::HandoverTimeModel::fixed(10.0);
    const std::string what = who + ": handover_time";
    const auto at_least = [&](double value, double bound, const std::string& field, const std::string& bound_text,
                              Position where) {
      if (std::isfinite(value) && value >= bound) return true;
      error(where, what + " " + field + " must be >= " + bound_text + " (got " + format_number(value) + ")");
      return false;
    };
    switch (t.model_case()) {
      case config::HandoverTime::kFixedS:
        at_least(t.fixed_s(), 0.0, "fixed_s", "0", at.at("fixed_s"));
        return office::HandoverTimeModel::fixed(t.fixed_s());
      case config::HandoverTime::kUniform: {
        const config::UniformTime& u = t.uniform();
        const Locator ul = at.nested("uniform");
        if (at_least(u.min_s(), 0.0, "uniform min_s", "0", ul.at("min_s")))
          at_least(u.max_s(), u.min_s(), "uniform max_s", "min_s " + format_number(u.min_s()), ul.at("max_s"));
        return office::HandoverTimeModel::uniform(u.min_s(), u.max_s());
      }
      case config::HandoverTime::kNormal: {
        const config::NormalTime& n = t.normal();
        const Locator nl = at.nested("normal");
        const double max_s = n.has_max_s() ? n.max_s() : n.mean_s() + 4.0 * n.sd_s();
        at_least(n.mean_s(), 0.0, "normal mean_s", "0", nl.at("mean_s"));
        at_least(n.sd_s(), 0.0, "normal sd_s", "0", nl.at("sd_s"));
        if (at_least(n.min_s(), 0.0, "normal min_s", "0", nl.at("min_s")) && n.has_max_s())
          at_least(max_s, n.min_s(), "normal max_s", "min_s " + format_number(n.min_s()), nl.at("max_s"));
        return office::HandoverTimeModel::normal(n.mean_s(), n.sd_s(), n.min_s(), max_s);
      }
      case config::HandoverTime::MODEL_NOT_SET: break;
    }
    error(at.self(), what + " names no model (fixed_s, uniform or normal)");
    return office::HandoverTimeModel::fixed(10.0);
  }

  // A time of day written in the file, or an error at `where`.
  std::optional<double> clock_time(const std::string& text, const std::string& what, Position where) {
    if (const auto t = office::parse_clock(text)) return t;
    error(where, what + " '" + text + "' is not a time of day HH:MM or HH:MM:SS (00:00 .. 24:00)");
    return std::nullopt;
  }

  void office(const config::Scenario& file, const Locator& root, Scenario& out) {
    const std::size_t errors_before = errors_.size();
    office::OfficeSpec spec;
    if (!file.day_start().empty()) {
      if (const auto t = clock_time(file.day_start(), "day_start", root.at("day_start"))) {
        if (*t >= office::kSecondsPerDay)
          error(root.at("day_start"), "day_start '" + file.day_start() + "' must be before 24:00");
        spec.clock.day_start_s = *t;
      }
    }
    if (file.people_size() == 0 && file.objects_size() == 0 && file.loading_stations_size() == 0) return;

    // Rooms and places share the office's one namespace of places.
    for (const RoomSpec& r : out.rooms) {
      office::Place room{r.name, office::PlaceKind::room, "", {0.0, 0.0}, 1.0};
      const geometry::Rect area = r.bounds.value_or(geometry::Rect{0.0, 0.0, out.world.width, out.world.height});
      room.position = {0.5 * (area.min_x + area.max_x), 0.5 * (area.min_y + area.max_y)};
      room.radius = std::max(1.0, 0.5 * std::hypot(area.max_x - area.min_x, area.max_y - area.min_y));
      if (!std::isfinite(room.radius)) room.radius = 1.0;  // the world's size was reported already
      spec.places.push_back(std::move(room));
    }
    for (const auto& [p, at] : office_places_) {
      if (room_lines_.count(p.name) != 0) {
        error(at, "place '" + p.name + "' has the name of a room (line " + std::to_string(room_lines_.at(p.name)) +
                      "); with people, objects or loading stations they share one namespace");
        continue;
      }
      spec.places.push_back(p);
    }

    std::map<std::string, int> people;
    for (int i = 0; i < file.people_size(); ++i) {
      const config::Person& p = file.people(i);
      const Locator at = root.nested("people", i);
      if (!unique_name("person", p.name(), at.at("name"), people)) continue;
      const std::string who = "person '" + p.name() + "'";
      office::Person person;
      person.name = p.name();
      person.desk = p.desk();
      if (p.desk().empty())
        error(at.self(), who + ": desk is missing");
      else
        office_place(who, p.desk(), at.at("desk"));
      std::optional<office::DailyInterval> previous;
      for (int k = 0; k < p.presence_size(); ++k) {
        const config::DailyInterval& d = p.presence(k);
        const Locator il = at.nested("presence", k);
        const auto start = clock_time(d.start(), who + ": presence start", il.at("start"));
        const auto end = clock_time(d.end(), who + ": presence end", il.at("end"));
        if (!start || !end) continue;
        const office::DailyInterval interval{*start, *end};
        const std::string range = d.start() + "-" + d.end();
        if (*start >= *end) {
          error(il.self(), who + ": presence " + range + (*start > *end ? " ends before it starts" : " is empty"));
          continue;
        }
        if (previous && interval.start_s < previous->end_s) {
          error(il.self(), who + ": presence " + range + " overlaps or comes before the previous interval " +
                               office::format_clock(previous->start_s) + "-" + office::format_clock(previous->end_s));
          continue;
        }
        previous = interval;
        person.presence.push_back(interval);
      }
      person.handover_time = handover_time(p.has_handover_time(), p.handover_time(), who, at.nested("handover_time"));
      spec.people.push_back(std::move(person));
    }

    std::map<std::string, int> stations;
    for (int i = 0; i < file.loading_stations_size(); ++i) {
      const config::LoadingStation& s = file.loading_stations(i);
      const Locator at = root.nested("loading_stations", i);
      if (s.place().empty()) {
        error(at.self(), "loading station: place is missing");
        continue;
      }
      const std::string who = "loading station at '" + s.place() + "'";
      if (!office_place(who, s.place(), at.at("place"))) continue;
      if (const auto [it, fresh] = stations.emplace(s.place(), at.at("place").line); !fresh) {
        error(at.at("place"), "duplicate loading station at '" + s.place() + "' (first defined at line " +
                                  std::to_string(it->second) + ")");
        continue;
      }
      spec.stations.push_back(
          {s.place(), handover_time(s.has_handover_time(), s.handover_time(), who, at.nested("handover_time"))});
    }

    std::map<std::string, const RobotSpec*> robots;
    for (const auto* list : {&out.world.robots_at_start, &out.world.known_robots})
      for (const RobotSpec& r : *list) robots.emplace(r.id, &r);
    std::map<std::string, std::uint32_t> carried;  // robot id -> objects it carries at the start
    std::map<std::string, int> objects;
    for (int i = 0; i < file.objects_size(); ++i) {
      const config::OfficeObject& o = file.objects(i);
      const Locator at = root.nested("objects", i);
      if (const auto problem = robot_id_problem(o.id())) {
        std::string text = *problem;
        text.replace(0, 5, "object");  // "robot id ..." -> "object id ..."
        error(at.at("id"), text);
        continue;
      }
      if (const auto [it, fresh] = objects.emplace(o.id(), at.at("id").line); !fresh) {
        error(at.at("id"), "duplicate object id " + o.id() + " (first defined at line " + std::to_string(it->second) + ")");
        continue;
      }
      const std::string who = "object '" + o.id() + "'";
      if (o.kind().empty()) error(at.self(), who + ": kind is missing (letter, book, envelope, ...)");
      office::ObjectItem item{o.id(), o.kind(), o.colour(), {}};
      switch (o.location_case()) {
        case config::OfficeObject::kPlace:
          office_place(who, o.place(), at.at("place"));
          item.location = office::ObjectLocation::at_place(o.place());
          break;
        case config::OfficeObject::kCarrier: {
          item.location = office::ObjectLocation::carried_by(o.carrier());
          const auto robot = robots.find(o.carrier());
          if (robot == robots.end()) {
            error(at.at("carrier"), who + ": carrier '" + o.carrier() + "' is not a robot of this scenario");
          } else if (const std::uint32_t n = ++carried[o.carrier()]; n > robot->second->capacity) {
            error(at.at("carrier"), who + ": robot " + o.carrier() + " would carry " + std::to_string(n) +
                                        " objects, its capacity is " + std::to_string(robot->second->capacity));
          }
          break;
        }
        case config::OfficeObject::LOCATION_NOT_SET:
          error(at.self(), who + ": place or carrier is missing");
          break;
      }
      spec.objects.push_back(std::move(item));
    }

    if (errors_.size() != errors_before) return;
    // Everything above is checked with its position; the office's own rules are the backstop.
    for (const std::string& problem : office::office_spec_problems(spec)) error(root.self(), "office: " + problem);
    if (errors_.size() == errors_before) out.office = std::move(spec);
  }

  static std::string world_text(const WorldSpec& w) {
    return "[0, " + format_number(w.width) + "] x [0, " + format_number(w.height) + "]";
  }

  std::optional<Kinematics> kinematics(config::Kinematics k, const std::string& who,
                                       Position at) {
    switch (k) {
      case config::HOLONOMIC: return Kinematics::Holonomic;
      case config::UNICYCLE: return Kinematics::Unicycle;
      case config::KINEMATICS_UNSPECIFIED: return std::nullopt;
      default: break;
    }
    error(at, who + ": unknown kinematics value " + std::to_string(static_cast<int>(k)));
    return Kinematics::Holonomic;
  }

  // Body and limits shared by all robots: the fallback for what a robot leaves out.
  RobotSpec attach_defaults(const config::Robot& r, const Locator& at) {
    const std::string who = "attach_defaults";
    for (const char* meaningless : {"id", "start", "spawn_at_start"}) {
      const pb::FieldDescriptor* f = config::Robot::descriptor()->FindFieldByName(meaningless);
      if (r.GetReflection()->HasField(r, f)) {
        error(at.at(meaningless), who + ": " + meaningless + " has no meaning here; remove it");
      }
    }
    const RobotSpec builtin;
    RobotSpec spec;
    spec.kinematics = kinematics(r.kinematics(), who, at.at("kinematics"))
                          .value_or(Kinematics::Holonomic);
    spec.radius = positive(r.has_radius(), r.radius(), builtin.radius, who + ": radius", at.at("radius"));
    spec.max_speed = positive(r.has_max_speed(), r.max_speed(), builtin.max_speed,
                              who + ": max_speed", at.at("max_speed"));
    spec.max_omega = positive(r.has_max_omega(), r.max_omega(), builtin.max_omega,
                              who + ": max_omega", at.at("max_omega"));
    spec.kind = r.kind();
    spec.capacity = r.has_capacity() ? r.capacity() : builtin.capacity;
    if (r.has_sensors()) spec.sensors = sensors(r.sensors(), who, at.nested("sensors"));
    return spec;
  }

  SensorSpec sensors(const config::Sensors& s, const std::string& who, const Locator& at) {
    SensorSpec out;
    const auto non_negative = [&](double value, const std::string& what, Position where) {
      if (!(std::isfinite(value) && value >= 0.0)) {
        error(where, who + ": " + what + " must be >= 0 (got " + format_number(value) + ")");
      }
      return value;
    };
    if (s.has_range()) {
      const config::RangeSensor& r = s.range();
      const Locator rl = at.nested("range");
      if (r.rays() < 1 || r.rays() > 100000) {
        error(rl.at("rays"), who + ": range sensor rays must be 1 .. 100000 (got " + std::to_string(r.rays()) + ")");
      }
      out.range.rays = static_cast<int>(std::min<std::uint32_t>(r.rays(), 100000));
      out.range.fov_rad = r.has_fov_rad() ? r.fov_rad() : 2.0 * M_PI;
      if (!(out.range.fov_rad > 0.0 && out.range.fov_rad <= 2.0 * M_PI + 1e-9)) {
        error(rl.at("fov_rad"), who + ": range sensor fov_rad must be in (0, 2 pi] (got " +
                                    format_number(out.range.fov_rad) + ")");
      }
      out.range.max_range_m = positive(true, r.max_range_m(), 0.0, who + ": range sensor max_range_m", rl.at("max_range_m"));
      out.range.noise_stddev_m = non_negative(r.noise_stddev_m(), "range sensor noise_stddev_m", rl.at("noise_stddev_m"));
    }
    if (s.has_doors()) {
      const Locator dl = at.nested("doors");
      out.doors.range_m = positive(true, s.doors().range_m(), 0.0, who + ": door sensor range_m", dl.at("range_m"));
      out.doors.angle_noise_rad = non_negative(s.doors().angle_noise_rad(), "door sensor angle_noise_rad",
                                               dl.at("angle_noise_rad"));
    }
    if (s.has_pose()) {
      const Locator pl = at.nested("pose");
      out.pose.position_noise_m = non_negative(s.pose().position_noise_m(), "pose sensor position_noise_m",
                                               pl.at("position_noise_m"));
      out.pose.heading_noise_rad = non_negative(s.pose().heading_noise_rad(), "pose sensor heading_noise_rad",
                                                pl.at("heading_noise_rad"));
    }
    return out;
  }

  void robots(const config::Scenario& file, const Locator& root, WorldSpec& out) {
    std::map<std::string, int> first_line;  // id -> line of its first definition
    for (int i = 0; i < file.robots_size(); ++i) {
      const config::Robot& r = file.robots(i);
      const Locator at = root.nested("robots", i);
      const std::string who = "robot " + (r.id().empty() ? "#" + std::to_string(i) : r.id());

      if (const auto problem = robot_id_problem(r.id())) {
        error(at.at("id"), *problem);
      } else if (const auto [it, fresh] = first_line.emplace(r.id(), at.at("id").line); !fresh) {
        error(at.at("id"), "duplicate robot id " + r.id() + " (first defined at line " +
                               std::to_string(it->second) + ")");
      }

      RobotSpec spec;
      spec.id = r.id();
      const auto k = kinematics(r.kinematics(), who, at.at("kinematics"));
      if (!k) error(at.at("kinematics"), who + ": kinematics must be HOLONOMIC or UNICYCLE");
      spec.kinematics = k.value_or(Kinematics::Holonomic);
      const RobotSpec& d = out.attach_defaults;
      spec.radius = positive(r.has_radius(), r.radius(), d.radius, who + ": radius", at.at("radius"));
      spec.max_speed = positive(r.has_max_speed(), r.max_speed(), d.max_speed,
                                who + ": max_speed", at.at("max_speed"));
      spec.max_omega = positive(r.has_max_omega(), r.max_omega(), d.max_omega,
                                who + ": max_omega", at.at("max_omega"));
      spec.kind = r.kind().empty() ? d.kind : r.kind();
      spec.capacity = r.has_capacity() ? r.capacity() : d.capacity;
      spec.sensors = r.has_sensors() ? sensors(r.sensors(), who, at.nested("sensors")) : d.sensors;

      if (!r.has_start()) {
        error(at.self(), who + ": start pose is missing");
      } else {
        spec.start = {r.start().x(), r.start().y(), r.start().theta()};
        place(who, spec, at.at("start"), out);
      }
      (r.spawn_at_start() ? out.robots_at_start : out.known_robots).push_back(spec);
    }
  }

  // Checks the start pose against the world, the obstacles and the robots placed before.
  void place(const std::string& who, const RobotSpec& spec, Position at, const WorldSpec& world) {
    const geometry::Pose2& p = spec.start;
    if (!all_finite({p.x, p.y, p.theta})) {
      error(at, who + ": start pose is not finite");
      return;
    }
    if (!(std::isfinite(spec.radius) && spec.radius > 0.0)) return;  // reported already
    const std::string where = who + " at " + point_text(p.x, p.y);
    const geometry::Vec2 center = p.position();
    if (world_valid_ && !fits_in_world(world.width, world.height, center, spec.radius)) {
      error(at, where + " does not fit inside the world " + world_text(world));
    }
    for (const auto& [index, rect] : checked_obstacles_) {
      if (geometry::circle_overlaps(rect, center, spec.radius)) {
        error(at, where + " overlaps obstacle " + std::to_string(index));
      }
    }
    if (obstacle_map_) {
      if (const auto hit = obstacle_map_->overlap(center, spec.radius)) {
        error(at, where + " overlaps " + obstacle_text(*hit));
      }
    }
    for (const DoorSpec& door : world.doors) {
      if (disc_overlaps_leaf(door.leaf(door.angle), center, spec.radius)) {
        error(at, where + " overlaps door " + door.id);
      }
    }
    for (const RobotSpec& other : placed_) {
      if (discs_overlap(center, spec.radius, other.start.position(), other.radius)) {
        error(at, where + " overlaps robot " + other.id);
      }
    }
    placed_.push_back(spec);
  }

  void simulation(const config::Simulation& s, const Locator& at, Scenario& out) {
    SimulationSettings& settings = out.simulation;
    const SimulationSettings defaults;
    switch (s.mode()) {
      case config::CLOCK_MODE_UNSPECIFIED:
      case config::LOCKSTEP: settings.mode = ClockMode::Lockstep; break;
      case config::PACED: settings.mode = ClockMode::Paced; break;
      default:
        error(at.at("mode"),
              "simulation: unknown mode value " + std::to_string(static_cast<int>(s.mode())));
    }
    settings.step_s = positive(s.has_step_s(), s.step_s(), defaults.step_s, "simulation: step_s",
                               at.at("step_s"));
    settings.warp = positive(s.has_warp(), s.warp(), defaults.warp, "simulation: warp", at.at("warp"));
    settings.seed = s.seed();
    settings.ack_timeout_s = positive(s.has_ack_timeout_s(), s.ack_timeout_s(), defaults.ack_timeout_s,
                                      "simulation: ack_timeout_s", at.at("ack_timeout_s"));
    out.world.command_timeout_s =
        positive(s.has_command_timeout_s(), s.command_timeout_s(), WorldSpec{}.command_timeout_s,
                 "simulation: command_timeout_s", at.at("command_timeout_s"));
  }

  const std::string& source_;
  std::vector<ScenarioError>& errors_;
  bool world_valid_ = false;
  std::vector<std::pair<int, geometry::Rect>> checked_obstacles_;  // index in the file, rect
  std::vector<int> checked_polygon_index_;  // file index of each polygon that passed
  std::unique_ptr<ObstacleMap> obstacle_map_;  // passed polygons and maps; set when world_valid_
  std::map<std::string, int> room_lines_;   // room name -> line of its definition
  std::string base_dir_;                    // of the scenario file, with a trailing '/', or ""
  std::vector<RobotSpec> placed_;
  // Places that passed their checks, as the office sees them, with where their name is written.
  std::vector<std::pair<office::Place, Position>> office_places_;
};

}  // namespace

std::string ScenarioLoadResult::error_text() const { return configfile::error_text(errors); }

ScenarioLoadResult load_scenario_text(const std::string& text, const std::string& source_name) {
  ScenarioLoadResult result;
  ParseInfoTree tree;
  config::Scenario file;
  if (!configfile::parse_text_format(text, source_name, file, tree, result.errors)) return result;
  Scenario scenario = ScenarioChecker(source_name, result.errors).check(file, tree);
  configfile::sort_by_position(result.errors);
  if (result.errors.empty()) result.scenario = std::move(scenario);
  return result;
}

ScenarioLoadResult load_scenario_file(const std::string& path) {
  ScenarioLoadResult result;
  const std::optional<std::string> text = configfile::read_text_file(path, result.errors);
  return text ? load_scenario_text(*text, path) : result;
}

}  // namespace autonomy::sim
