#include "services/courier/core/scheduler/schedule_json.hpp"

#include "common/grid/map_loader.hpp"
#include "services/courier/core/scheduler/travel_times.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <map>

namespace autonomy::courier::scheduling {

namespace {

using nlohmann::json;

// Input errors are thrown inside this file only and become ParsedProblem::error.
struct InputError {
  std::string message;
};

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw InputError{path + ": " + what};
}

std::string type_name(const json& v) {
  return v.type_name();
}

const json& member(const json& object, const char* key, const std::string& path) {
  const auto it = object.find(key);
  if (it == object.end()) fail(path, std::string("missing \"") + key + "\"");
  return *it;
}

const json* optional_member(const json& object, const char* key) {
  const auto it = object.find(key);
  return it == object.end() || it->is_null() ? nullptr : &*it;
}

void expect_object(const json& v, const std::string& path,
                   std::initializer_list<const char*> keys) {
  if (!v.is_object()) fail(path, "expected an object, got " + type_name(v));
  for (auto it = v.begin(); it != v.end(); ++it) {
    bool known = false;
    for (const char* k : keys) known = known || it.key() == k;
    if (!known) fail(path + "/" + it.key(), "unknown field");
  }
}

const json& array_member(const json& object, const char* key, const std::string& path) {
  const json& v = member(object, key, path);
  if (!v.is_array()) fail(path + "/" + key, "expected an array, got " + type_name(v));
  return v;
}

std::string string_of(const json& v, const std::string& path) {
  if (!v.is_string()) fail(path, "expected a string, got " + type_name(v));
  return v.get<std::string>();
}

double number_of(const json& v, const std::string& path) {
  if (!v.is_number()) fail(path, "expected a number, got " + type_name(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(path, "not a finite number");
  return d;
}

double non_negative(const json& v, const std::string& path) {
  const double d = number_of(v, path);
  if (d < 0) fail(path, "must be >= 0");
  return d;
}

// Seconds of the day (a number) or "HH:MM[:SS]".
double time_of(const json& v, const std::string& path) {
  if (v.is_string()) {
    const auto t = parse_time_of_day(v.get<std::string>());
    if (!t) fail(path, "'" + v.get<std::string>() + "' is not a time of day (HH:MM or HH:MM:SS)");
    return *t;
  }
  if (!v.is_number())
    fail(path, "expected a time (seconds of the day or \"HH:MM\"), got " + type_name(v));
  return number_of(v, path);
}

class Reader {
 public:
  Reader(const json& doc, std::string base_dir) : doc_(doc), base_dir_(std::move(base_dir)) {}

  SchedulingProblem read() {
    expect_object(
        doc_, "",
        {"now", "locations", "travel_s", "map", "people", "couriers", "jobs", "hallway_y"});
    p_.now_s = time_of(member(doc_, "now", ""), "/now");
    read_locations();
    read_people();
    read_couriers();
    read_jobs();
    read_prefixes();
    if (const json* h = optional_member(doc_, "hallway_y"))
      p_.hallway_y_m = number_of(*h, "/hallway_y");
    const json* matrix = optional_member(doc_, "travel_s");
    const json* map = optional_member(doc_, "map");
    if ((matrix != nullptr) == (map != nullptr))
      fail("", "give exactly one of \"travel_s\" (a matrix) and \"map\" (a map with places)");
    if (matrix) read_matrix(*matrix);
    if (map) read_map(*map);
    if (std::string e = problem_error(p_); !e.empty()) fail("", e);
    return std::move(p_);
  }

 private:
  int location_index(const json& v, const std::string& path) {
    if (v.is_number_integer()) {
      const auto i = v.get<long long>();
      if (i < 0 || static_cast<std::size_t>(i) >= p_.locations.size())
        fail(path, "location index " + std::to_string(i) + " is out of range");
      return static_cast<int>(i);
    }
    const std::string name = string_of(v, path);
    const auto it = locations_.find(name);
    if (it == locations_.end()) fail(path, "no location '" + name + "'");
    return it->second;
  }

  int person_index(const json& v, const std::string& path) {
    const std::string name = string_of(v, path);
    const auto it = people_.find(name);
    if (it == people_.end()) fail(path, "no person '" + name + "'");
    return it->second;
  }

  void read_locations() {
    const json& a = array_member(doc_, "locations", "");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string path = "/locations/" + std::to_string(i);
      const json& l = a[i];
      expect_object(l, path, {"name", "room", "x", "y", "station_handover_s"});
      Location loc;
      loc.name = string_of(member(l, "name", path), path + "/name");
      if (loc.name.empty()) fail(path + "/name", "empty");
      if (!locations_.emplace(loc.name, static_cast<int>(i)).second)
        fail(path + "/name", "'" + loc.name + "' is already a location");
      if (const json* r = optional_member(l, "room")) loc.room = string_of(*r, path + "/room");
      const json* x = optional_member(l, "x");
      const json* y = optional_member(l, "y");
      if ((x != nullptr) != (y != nullptr)) fail(path, "give both \"x\" and \"y\" or neither");
      if (x) loc.x_m = number_of(*x, path + "/x"), loc.y_m = number_of(*y, path + "/y");
      if (const json* h = optional_member(l, "station_handover_s"))
        loc.station_handover_s = non_negative(*h, path + "/station_handover_s");
      p_.locations.push_back(std::move(loc));
    }
  }

  void read_people() {
    const json* a = optional_member(doc_, "people");
    if (!a) return;
    if (!a->is_array()) fail("/people", "expected an array, got " + type_name(*a));
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string path = "/people/" + std::to_string(i);
      const json& v = (*a)[i];
      expect_object(v, path, {"name", "handover_s", "presence"});
      Person person;
      person.name = string_of(member(v, "name", path), path + "/name");
      if (person.name.empty()) fail(path + "/name", "empty");
      if (!people_.emplace(person.name, static_cast<int>(i)).second)
        fail(path + "/name", "'" + person.name + "' is already a person");
      person.handover_s = non_negative(member(v, "handover_s", path), path + "/handover_s");
      if (const json* w = optional_member(v, "presence")) {
        if (!w->is_array()) fail(path + "/presence", "expected an array of [from, to] pairs");
        for (std::size_t k = 0; k < w->size(); ++k) {
          const std::string wp = path + "/presence/" + std::to_string(k);
          const json& pair = (*w)[k];
          if (!pair.is_array() || pair.size() != 2) fail(wp, "expected [from, to]");
          TimeWindow tw{time_of(pair[0], wp + "/0"), time_of(pair[1], wp + "/1")};
          if (tw.end_s < tw.start_s) fail(wp, "ends before it starts");
          if (!person.presence.empty() && tw.start_s < person.presence.back().end_s)
            fail(wp, "windows must be sorted and must not overlap");
          person.presence.push_back(tw);
        }
      }
      p_.people.push_back(std::move(person));
    }
  }

  void read_couriers() {
    const json& a = array_member(doc_, "couriers", "");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string path = "/couriers/" + std::to_string(i);
      const json& v = a[i];
      expect_object(v, path, {"id", "capacity", "location", "available", "forced_prefix"});
      Courier c;
      c.id = string_of(member(v, "id", path), path + "/id");
      if (!couriers_.emplace(c.id, static_cast<int>(i)).second)
        fail(path + "/id", "'" + c.id + "' is already a courier");
      const json& cap = member(v, "capacity", path);
      if (!cap.is_number_integer() || cap.get<long long>() < 1 || cap.get<long long>() > 16)
        fail(path + "/capacity", "expected an integer 1..16");
      c.capacity = cap.get<int>();
      c.location = location_index(member(v, "location", path), path + "/location");
      c.available_s = p_.now_s;
      if (const json* t = optional_member(v, "available"))
        c.available_s = time_of(*t, path + "/available");
      p_.couriers.push_back(std::move(c));
    }
  }

  Place place_of(const json& v, const std::string& path) {
    expect_object(v, path, {"location", "person"});
    Place pl;
    pl.location = location_index(member(v, "location", path), path + "/location");
    if (const json* person = optional_member(v, "person"))
      pl.person = person_index(*person, path + "/person");
    return pl;
  }

  void read_jobs() {
    const json& a = array_member(doc_, "jobs", "");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string path = "/jobs/" + std::to_string(i);
      const json& v = a[i];
      expect_object(v, path, {"id", "object", "pickup", "delivery", "deadline", "aboard"});
      Job job;
      job.id = string_of(member(v, "id", path), path + "/id");
      if (!jobs_.emplace(job.id, static_cast<int>(i)).second)
        fail(path + "/id", "'" + job.id + "' is already a job");
      const json& object = member(v, "object", path);
      expect_object(object, path + "/object", {"kind", "colour"});
      job.object.kind = string_of(member(object, "kind", path + "/object"), path + "/object/kind");
      if (const json* colour = optional_member(object, "colour"))
        job.object.colour = string_of(*colour, path + "/object/colour");
      const json* aboard = optional_member(v, "aboard");
      const json* pickup = optional_member(v, "pickup");
      if (aboard) {
        const std::string id = string_of(*aboard, path + "/aboard");
        const auto it = couriers_.find(id);
        if (it == couriers_.end()) fail(path + "/aboard", "no courier '" + id + "'");
        job.status = JobStatus::kAboard;
        job.aboard_courier = it->second;
        if (pickup) fail(path + "/pickup", "a job aboard a courier has no pickup");
      } else {
        if (!pickup) fail(path, "missing \"pickup\" (or \"aboard\": COURIER when already loaded)");
        job.pickup = place_of(*pickup, path + "/pickup");
      }
      job.delivery = place_of(member(v, "delivery", path), path + "/delivery");
      if (const json* d = optional_member(v, "deadline"))
        job.deadline_s = time_of(*d, path + "/deadline");
      p_.jobs.push_back(std::move(job));
    }
  }

  void read_prefixes() {
    const json& a = doc_.at("couriers");
    for (std::size_t i = 0; i < a.size(); ++i) {
      const json* prefix = optional_member(a[i], "forced_prefix");
      if (!prefix) continue;
      const std::string path = "/couriers/" + std::to_string(i) + "/forced_prefix";
      if (!prefix->is_array()) fail(path, "expected an array of {\"job\", \"stop\"}");
      for (std::size_t k = 0; k < prefix->size(); ++k) {
        const std::string sp = path + "/" + std::to_string(k);
        const json& s = (*prefix)[k];
        expect_object(s, sp, {"job", "stop"});
        const std::string id = string_of(member(s, "job", sp), sp + "/job");
        const auto it = jobs_.find(id);
        if (it == jobs_.end()) fail(sp + "/job", "no job '" + id + "'");
        const std::string kind = string_of(member(s, "stop", sp), sp + "/stop");
        if (kind != "pickup" && kind != "delivery")
          fail(sp + "/stop", "expected \"pickup\" or \"delivery\"");
        p_.couriers[i].forced_prefix.push_back(
            {it->second, kind == "pickup" ? StopKind::kPickup : StopKind::kDelivery});
      }
    }
  }

  void read_matrix(const json& m) {
    const std::size_t n = p_.locations.size();
    if (!m.is_array() || m.size() != n)
      fail("/travel_s", "expected " + std::to_string(n) + " rows (one per location)");
    p_.travel = TravelMatrix(n);
    for (std::size_t a = 0; a < n; ++a) {
      const std::string rp = "/travel_s/" + std::to_string(a);
      if (!m[a].is_array() || m[a].size() != n)
        fail(rp, "expected " + std::to_string(n) + " entries");
      for (std::size_t b = 0; b < n; ++b) {
        const json& v = m[a][b];
        const std::string vp = rp + "/" + std::to_string(b);
        // null or "inf": no route.
        if (v.is_null() || (v.is_string() && v.get<std::string>() == "inf")) {
          if (a == b) fail(vp, "the diagonal must be 0");
          p_.travel.set(a, b, kNoRoute);
          continue;
        }
        const double t = non_negative(v, vp);
        if (a == b && t != 0.0) fail(vp, "the diagonal must be 0");
        p_.travel.set(a, b, t);
      }
    }
  }

  void read_map(const json& m) {
    expect_object(m, "/map", {"yaml", "speed_mps", "closed"});
    std::string yaml = string_of(member(m, "yaml", "/map"), "/map/yaml");
    if (!yaml.empty() && yaml[0] != '/' && !base_dir_.empty()) yaml = base_dir_ + "/" + yaml;
    const double speed = number_of(member(m, "speed_mps", "/map"), "/map/speed_mps");
    if (speed <= 0) fail("/map/speed_mps", "must be > 0");
    auto loaded = grid::load_ros_map(yaml);
    if (!loaded.ok()) fail("/map/yaml", loaded.error);
    const grid::OccupancyRaster& raster = loaded.map->raster;
    std::vector<MapPosition> places;
    for (std::size_t i = 0; i < p_.locations.size(); ++i) {
      const Location& l = p_.locations[i];
      if (!l.x_m)
        fail("/locations/" + std::to_string(i),
             "needs \"x\" and \"y\" when travel comes from a map");
      places.push_back({*l.x_m, *l.y_m});
    }
    // Closed doors: boxes [x_min, y_min, x_max, y_max] in map metres; cells whose centre is inside.
    std::vector<grid::Cell> blocked;
    if (const json* closed = optional_member(m, "closed")) {
      if (!closed->is_array())
        fail("/map/closed", "expected an array of [x_min, y_min, x_max, y_max]");
      const auto& o = raster.origin();
      for (std::size_t k = 0; k < closed->size(); ++k) {
        const std::string bp = "/map/closed/" + std::to_string(k);
        const json& box = (*closed)[k];
        if (!box.is_array() || box.size() != 4) fail(bp, "expected [x_min, y_min, x_max, y_max]");
        double b[4];
        for (std::size_t q = 0; q < 4; ++q) b[q] = number_of(box[q], bp + "/" + std::to_string(q));
        if (b[2] < b[0] || b[3] < b[1]) fail(bp, "max below min");
        const double res = raster.resolution_m();
        for (int row = 0; row < raster.height(); ++row)
          for (int col = 0; col < raster.width(); ++col) {
            const double u = (col + 0.5) * res, v = (row + 0.5) * res;
            const double x = o.x + std::cos(o.yaw) * u - std::sin(o.yaw) * v;
            const double y = o.y + std::sin(o.yaw) * u + std::cos(o.yaw) * v;
            if (x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3]) blocked.push_back({col, row});
          }
      }
    }
    auto times = travel_times_from_map(raster, places, speed, blocked);
    if (!times.ok()) fail("/map", times.error);
    p_.travel = std::move(times.matrix);
  }

  const json& doc_;
  std::string base_dir_;
  SchedulingProblem p_;
  std::map<std::string, int> locations_, people_, couriers_, jobs_;
};

json time_json(double s) {
  return format_time_of_day(s);
}

}  // namespace

std::optional<double> parse_time_of_day(const std::string& text) {
  int h = 0, m = 0, s = 0, used = 0;
  if (std::sscanf(text.c_str(), "%2d:%2d:%2d%n", &h, &m, &s, &used) == 3 &&
      static_cast<std::size_t>(used) == text.size()) {
  } else if (s = 0, used = 0; std::sscanf(text.c_str(), "%2d:%2d%n", &h, &m, &used) == 2 &&
                              static_cast<std::size_t>(used) == text.size()) {
  } else {
    return std::nullopt;
  }
  if (h < 0 || h > 24 || m < 0 || m > 59 || s < 0 || s > 59 || (h == 24 && (m || s)))
    return std::nullopt;
  return h * 3600.0 + m * 60.0 + s;
}

std::string format_time_of_day(double seconds) {
  if (!std::isfinite(seconds)) return "never";
  long long t = std::llround(seconds);
  const long long day = 86400;
  const long long days = t >= 0 ? t / day : -((-t + day - 1) / day);
  t -= days * day;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02lld:%02lld:%02lld", t / 3600, t / 60 % 60, t % 60);
  std::string out = buf;
  if (days != 0) out += (days > 0 ? "+" : "") + std::to_string(days) + "d";
  return out;
}

ParsedProblem problem_from_json(const nlohmann::json& document, const std::string& base_dir) {
  ParsedProblem out;
  try {
    out.problem = Reader(document, base_dir).read();
  } catch (const InputError& e) {
    out.error = e.message;
  } catch (const json::exception& e) {  // a type surprise the checks above missed
    out.error = std::string("invalid problem: ") + e.what();
  }
  return out;
}

ParsedProblem problem_from_json_text(const std::string& text, const std::string& name,
                                     const std::string& base_dir) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n')
        ++line, column = 1;
      else
        ++column;
    }
    ParsedProblem out;
    std::string what = e.what();
    if (const auto colon = what.rfind(": "); colon != std::string::npos)
      what = what.substr(colon + 2);
    out.error = name + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what;
    return out;
  }
  ParsedProblem out = problem_from_json(doc, base_dir);
  if (!out.ok()) out.error = name + ": " + out.error;
  return out;
}

nlohmann::json schedule_to_json(const SchedulingProblem& p, const JobSchedule& s) {
  json out;
  out["engine"] = s.engine;
  out["status"] = to_string(s.status);
  out["reason"] = s.reason;
  out["proved_optimal"] = s.proved_optimal;
  out["work"] = s.work;
  if (s.status == ScheduleStatus::kInvalidProblem) return out;
  auto job_id = [&](int j) { return p.jobs[static_cast<std::size_t>(j)].id; };
  auto courier_id = [&](int c) {
    return c >= 0 ? json(p.couriers[static_cast<std::size_t>(c)].id) : json();
  };
  auto location_name = [&](int l) { return p.locations[static_cast<std::size_t>(l)].name; };
  if (s.ok()) {
    out["objective"] = {{"late_jobs", s.objective.late_jobs},
                        {"lateness_s", s.objective.lateness_s},
                        {"completion_s", s.objective.completion_s},
                        {"travel_s", s.objective.travel_s},
                        {"interruptions", s.objective.interruptions}};
  }
  json routes = json::array();
  for (const CourierRoute& r : s.routes) {
    json stops = json::array();
    for (const ScheduledStop& st : r.stops) {
      json stop = {{"job", job_id(st.job)},
                   {"stop", to_string(st.kind)},
                   {"location", location_name(st.location)},
                   {"arrival_s", st.arrival_s},
                   {"arrival", time_json(st.arrival_s)},
                   {"handover_start_s", st.handover_start_s},
                   {"finish_s", st.finish_s},
                   {"finish", time_json(st.finish_s)},
                   {"same_visit", st.same_visit_as_previous}};
      if (st.person >= 0) stop["person"] = p.people[static_cast<std::size_t>(st.person)].name;
      stops.push_back(std::move(stop));
    }
    routes.push_back({{"courier", courier_id(r.courier)}, {"stops", std::move(stops)}});
  }
  out["routes"] = std::move(routes);
  json jobs = json::array();
  for (const JobOutcome& o : s.outcomes)
    jobs.push_back({{"job", job_id(o.job)},
                    {"courier", courier_id(o.courier)},
                    {"completion_s", o.completion_s},
                    {"completion", time_json(o.completion_s)},
                    {"lateness_s", o.lateness_s},
                    {"late", o.late}});
  out["jobs"] = std::move(jobs);
  json left = json::array();
  for (const UnschedulableJob& u : s.unschedulable)
    left.push_back({{"job", job_id(u.job)}, {"reason", to_string(u.reason)}, {"detail", u.detail}});
  out["unschedulable"] = std::move(left);
  json assumptions = json::array();
  for (const RoomAssumption& a : s.assumptions)
    assumptions.push_back({{"courier", courier_id(a.courier)},
                           {"room", a.room},
                           {"open_at_s", a.arrival_s},
                           {"open_at", time_json(a.arrival_s)},
                           {"location", location_name(a.location)}});
  out["assumptions"] = std::move(assumptions);
  return out;
}

}  // namespace autonomy::courier::scheduling
