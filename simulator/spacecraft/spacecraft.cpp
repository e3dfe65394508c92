#include "simulator/spacecraft/spacecraft.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace autonomy::sim::spacecraft {
namespace {

// Fixed devices; thrusters and electronics units come from the spec.
const char* const kFixedDevices[] = {"adcs", "ips", "camera", "power", "telecom", "storage"};

struct CommandShape {
  const char* name;
  int arguments;
  const char* argument;  // what the argument is, for messages
};

// The commands each kind of device takes besides `reset` (no arguments, every device).
std::vector<CommandShape> commands_of(const std::string& device) {
  if (device == "adcs") return {{"turn", 1, "target"}, {"set_mode", 1, "control mode"}};
  if (device == "ips") return {{"thrust", 1, "level"}, {"standby", 0, ""}};
  if (device == "camera") return {{"power_on", 0, ""}, {"off", 0, ""}, {"take_image", 1, "target"}};
  if (device == "power") return {{"switch_on", 1, "switch"}, {"switch_off", 1, "switch"}};
  if (device == "telecom") return {{"downlink", 0, ""}, {"stop", 0, ""}};
  return {};
}

std::string join(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

// A whole number written in decimal digits (at most 9), or nullopt.
std::optional<long> parse_int(const std::string& text) {
  if (text.empty() || text.size() > 9) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (errno != 0 || end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

bool switchable(const std::string& device) {
  return device == "camera" || device == "ips" || device == "telecom";
}

}  // namespace

const char* to_string(FaultKind kind) {
  switch (kind) {
    case FaultKind::StuckOn:
      return "stuck_on";
    case FaultKind::Failed:
      return "failed";
    case FaultKind::FalseSensor:
      return "false_sensor";
    case FaultKind::StuckClosed:
      return "stuck_closed";
    case FaultKind::NeverConfirmed:
      return "never_confirmed";
  }
  return "?";
}

std::optional<FaultKind> fault_kind_from_string(const std::string& text) {
  for (FaultKind k : {FaultKind::StuckOn, FaultKind::Failed, FaultKind::FalseSensor,
                      FaultKind::StuckClosed, FaultKind::NeverConfirmed})
    if (text == to_string(k)) return k;
  return std::nullopt;
}

Spacecraft::Spacecraft(SpacecraftSpec spec)
    : spec_(std::move(spec)),
      attitude_(spec_.attitude, spec_.targets),
      protection_(spec_.fault_protection) {
  if (!(std::isfinite(spec_.fault_protection.commander_timeout_s) &&
        spec_.fault_protection.commander_timeout_s >= 0.0))
    throw std::invalid_argument("spacecraft: commander_timeout_s must be >= 0");
  for (const char* d : kFixedDevices) device_names_.emplace_back(d);
  for (const std::string& t : spec_.attitude.thrusters) device_names_.push_back(t);
  for (const ElectronicsSpec& u : spec_.electronics) device_names_.push_back(u.name);
  std::sort(device_names_.begin(), device_names_.end());
  if (std::adjacent_find(device_names_.begin(), device_names_.end()) != device_names_.end())
    throw std::invalid_argument("spacecraft: a thruster or unit has the name of another device");
  if (!attitude_.knows_target(spec_.attitude.initial_target))
    throw std::invalid_argument("spacecraft: unknown initial target '" +
                                spec_.attitude.initial_target + "'");
  if (!attitude_.knows_mode(spec_.attitude.control_mode))
    throw std::invalid_argument("spacecraft: unknown control mode '" + spec_.attitude.control_mode +
                                "'");
  if (spec_.ion_engine.max_level < 1) throw std::invalid_argument("spacecraft: max_level < 1");
  if (spec_.camera.initial_mode != "off" && spec_.camera.initial_mode != "ready")
    throw std::invalid_argument("spacecraft: camera initial mode must be off or ready");
  camera_mode_ = spec_.camera.initial_mode;
  battery_wh_ = std::clamp(spec_.power.battery_soc, 0.0, 1.0) * spec_.power.battery_capacity_wh;
  for (const BusSwitchSpec& s : spec_.power.switches) {
    if (!switchable(s.device))
      throw std::invalid_argument("spacecraft: switch '" + s.name + "' feeds '" + s.device +
                                  "', not camera, ips or telecom");
    switch_closed_[s.name] = s.closed;
  }
  used_mb_ = std::clamp(spec_.storage.used_mb, 0.0, spec_.storage.capacity_mb);
  for (const auto& [name, closed] : switch_closed_)
    if (!closed) unpower(switch_named(name)->device);
  for (const FaultSpec& f : spec_.faults) {
    if (auto problem = fault_problem(f)) throw std::invalid_argument("spacecraft: " + *problem);
    armed_.push_back(f);
  }
}

// --- Faults -------------------------------------------------------------------------------------

std::vector<std::string> Spacecraft::reading_names() const {
  std::vector<std::string> names;
  for (const auto& [name, value] : true_readings()) names.push_back(name);
  return names;
}

std::optional<std::string> Spacecraft::fault_problem(const FaultSpec& f) const {
  const std::string what = std::string(to_string(f.kind)) + " fault '" + f.id + "'";
  const bool device = std::binary_search(device_names_.begin(), device_names_.end(), f.subject);
  const auto& thrusters = spec_.attitude.thrusters;
  switch (f.kind) {
    case FaultKind::StuckOn:
      if (f.subject != "camera" && f.subject != "ips")
        return what + ": subject must be camera or ips, not '" + f.subject + "'";
      break;
    case FaultKind::Failed:
    case FaultKind::NeverConfirmed:
      if (!device)
        return what + ": unknown device '" + f.subject + "' (devices: " + join(device_names_) + ")";
      break;
    case FaultKind::StuckClosed:
      if (std::find(thrusters.begin(), thrusters.end(), f.subject) == thrusters.end())
        return what + ": '" + f.subject + "' is not a thruster (thrusters: " + join(thrusters) +
               ")";
      break;
    case FaultKind::FalseSensor: {
      const auto names = reading_names();
      if (!std::binary_search(names.begin(), names.end(), f.subject))
        return what + ": unknown reading '" + f.subject + "'";
      if (!std::isfinite(f.value)) return what + ": value must be finite";
      break;
    }
  }
  if (!f.on_command.empty()) {
    std::istringstream words(f.on_command);
    std::string dev, cmd, extra;
    words >> dev >> cmd >> extra;
    if (dev.empty() || cmd.empty() || !extra.empty())
      return what + ": on_command must be \"device command\", not '" + f.on_command + "'";
    if (!std::binary_search(device_names_.begin(), device_names_.end(), dev))
      return what + ": on_command names unknown device '" + dev + "'";
  }
  if (f.at_s && !(std::isfinite(*f.at_s) && *f.at_s >= 0.0))
    return what + ": at_s must be a time >= 0";
  return std::nullopt;
}

CommandResult Spacecraft::inject(FaultSpec fault, const std::string& trigger) {
  if (fault.id.empty()) return {false, "fault id is empty"};
  const auto same_id = [&](const auto& list) {
    for (const auto& f : list)
      if (f.id == fault.id) return true;
    return false;
  };
  bool in_use = same_id(armed_);
  for (const ActiveFault& a : active_) in_use |= a.spec.id == fault.id;
  if (in_use) return {false, "fault id '" + fault.id + "' is already in use"};
  fault.at_s.reset();
  fault.on_command.clear();
  if (auto problem = fault_problem(fault)) return {false, *problem};
  activate(std::move(fault), trigger);
  return {true, ""};
}

bool Spacecraft::clear_fault(const std::string& id) {
  for (std::size_t i = 0; i < active_.size(); ++i)
    if (active_[i].spec.id == id) {
      end_fault(i, "cleared");
      return true;
    }
  const auto armed =
      std::find_if(armed_.begin(), armed_.end(), [&](const FaultSpec& f) { return f.id == id; });
  if (armed == armed_.end()) return false;
  armed_.erase(armed);
  return true;
}

void Spacecraft::activate(FaultSpec fault, const std::string& trigger) {
  events_.push_back({fault, true, trigger, "", time_s_});
  active_.push_back({std::move(fault), trigger});
}

void Spacecraft::end_fault(std::size_t index, const std::string& ended_by) {
  events_.push_back({active_[index].spec, false, active_[index].trigger, ended_by, time_s_});
  active_.erase(active_.begin() + static_cast<std::ptrdiff_t>(index));
}

const Spacecraft::ActiveFault* Spacecraft::active(FaultKind kind,
                                                  const std::string& subject) const {
  for (const ActiveFault& a : active_)
    if (a.spec.kind == kind && a.spec.subject == subject) return &a;
  return nullptr;
}

void Spacecraft::arm_event_faults(const Command& c) {
  const std::string key = c.device + " " + c.command;
  for (auto it = armed_.begin(); it != armed_.end();) {
    std::istringstream words(it->on_command);
    std::string dev, cmd;
    words >> dev >> cmd;
    if (!it->on_command.empty() && dev + " " + cmd == key) {
      FaultSpec f = std::move(*it);
      it = armed_.erase(it);
      activate(std::move(f), "on " + key);
    } else {
      ++it;
    }
  }
}

std::vector<FaultEvent> Spacecraft::take_fault_events() {
  std::vector<FaultEvent> out;
  out.swap(events_);
  return out;
}

// --- Commands -----------------------------------------------------------------------------------

CommandResult Spacecraft::submit(const Command& c) {
  commander_heard("command " + c.id + " from " + c.source);
  if (auto reason = check(c)) {
    ++rejected_;
    return {false, *reason};
  }
  ++accepted_;
  arm_event_faults(c);  // before the command takes effect: "the engine never confirmed it"
  if (!active(FaultKind::NeverConfirmed, c.device)) {
    execute(c);
    confirmations_[c.device] = {c.command, c.id, steps_};
  }
  return {true, ""};
}

std::optional<std::string> Spacecraft::check(const Command& c) const {
  if (!std::binary_search(device_names_.begin(), device_names_.end(), c.device))
    return "unknown device '" + c.device + "' (devices: " + join(device_names_) + ")";
  int arguments = -1;
  std::vector<std::string> names{"reset"};
  if (c.command == "reset") arguments = 0;
  for (const CommandShape& s : commands_of(c.device)) {
    names.emplace_back(s.name);
    if (c.command == s.name) arguments = s.arguments;
  }
  if (arguments < 0)
    return c.device + " has no command '" + c.command + "' (commands: " + join(names) + ")";
  if (static_cast<int>(c.arguments.size()) != arguments)
    return c.device + " " + c.command + " takes " + std::to_string(arguments) +
           " argument(s), got " + std::to_string(c.arguments.size());
  if (c.command == "reset") return std::nullopt;  // a failed unit must be able to take it
  if (active(FaultKind::Failed, c.device)) return c.device + " has failed (reset it)";
  for (const ElectronicsSpec& u : spec_.electronics)
    if (std::find(u.devices.begin(), u.devices.end(), c.device) != u.devices.end() &&
        active(FaultKind::Failed, u.name))
      return "commands to " + c.device + " pass through " + u.name + ", which has failed";
  if (!powered(c.device)) return c.device + " is unpowered (its bus switch is open)";

  const std::string arg = c.arguments.empty() ? "" : c.arguments[0];
  if (c.device == "adcs") {
    if (c.command == "turn") {
      if (!attitude_.knows_target(arg)) return "unknown target '" + arg + "'";
      if (attitude_.turning())
        return "adcs is turning to " + attitude_.turn_target() + " (" +
               number(attitude_.remaining_deg()) + " deg left)";
    } else if (!attitude_.knows_mode(arg)) {
      std::vector<std::string> modes;
      for (const ControlModeSpec& m : spec_.attitude.modes) modes.push_back(m.name);
      return "unknown control mode '" + arg + "' (modes: " + join(modes) + ")";
    }
  } else if (c.device == "ips") {
    if (c.command == "thrust") {
      const auto level = parse_int(arg);
      if (!level || *level < 1 || *level > spec_.ion_engine.max_level)
        return "thrust level '" + arg + "' is out of range 1.." +
               std::to_string(spec_.ion_engine.max_level);
      const double need = ips_power_w(static_cast<int>(*level));
      const double others = load_w() - ips_power_w(thrust_level_);
      const double available = spec_.power.solar_array_w - others +
                               (battery_wh_ > 0.0 ? spec_.power.max_discharge_w : 0.0);
      if (need > available)
        return "thrust level " + arg + " needs " + number(need) + " W, " + number(available) +
               " W available";
    }
  } else if (c.device == "camera") {
    if (c.command == "power_on" && camera_mode_ == "imaging") return "camera is imaging";
    if (c.command == "take_image") {
      if (!attitude_.knows_target(arg)) return "unknown target '" + arg + "'";
      if (camera_mode_ != "ready") return "camera is " + camera_mode_ + ", not ready";
      if (used_mb_ + spec_.camera.image_mb > spec_.storage.capacity_mb + 1e-9)
        return "storage full: " + number(used_mb_) + " of " + number(spec_.storage.capacity_mb) +
               " MB used, an image needs " + number(spec_.camera.image_mb) + " MB";
    }
  } else if (c.device == "power") {
    if (!switch_named(arg)) {
      std::vector<std::string> switches;
      for (const BusSwitchSpec& s : spec_.power.switches) switches.push_back(s.name);
      return "unknown switch '" + arg + "' (switches: " + join(switches) + ")";
    }
  } else if (c.device == "telecom") {
    if (c.command == "downlink") {
      if (downlinking_) return "telecom is downlinking";
      if (!window_at(time_s_)) {
        std::string next;
        for (const StationWindowSpec& w : spec_.telecom.windows)
          if (w.start_s > time_s_) {
            next = " (next: " + w.station + " at " + number(w.start_s) + " s)";
            break;
          }
        return "no ground station in view" + next;
      }
    }
  }
  return std::nullopt;
}

void Spacecraft::execute(const Command& c) {
  const std::string arg = c.arguments.empty() ? "" : c.arguments[0];
  if (c.command == "reset") {
    for (std::size_t i = 0; i < active_.size(); ++i)
      if (active_[i].spec.kind == FaultKind::Failed && active_[i].spec.subject == c.device &&
          active_[i].spec.reset_cures) {
        end_fault(i, "reset");
        break;
      }
    return;
  }
  if (c.device == "adcs") {
    if (c.command == "turn") attitude_.turn_to(arg);
    if (c.command == "set_mode") attitude_.set_mode(arg);
  } else if (c.device == "ips") {
    const bool stuck = active(FaultKind::StuckOn, "ips") && thrust_level_ > 0;
    if (c.command == "thrust") thrust_level_ = static_cast<int>(*parse_int(arg));
    if (c.command == "standby" && !stuck) thrust_level_ = 0;
  } else if (c.device == "camera") {
    const bool stuck = active(FaultKind::StuckOn, "camera") && camera_mode_ == "imaging";
    if (c.command == "power_on" && camera_mode_ == "off") camera_mode_ = "ready";
    if (c.command == "off" && !stuck) {
      camera_mode_ = "off";
      exposure_left_s_ = 0.0;
    }
    if (c.command == "take_image") {
      camera_mode_ = "imaging";
      exposure_left_s_ = spec_.camera.exposure_s;
      image_target_ = arg;
      image_on_target_ = !attitude_.turning() &&
                         attitude_.angle_to_deg(arg) <= spec_.attitude.pointing_tolerance_deg;
    }
  } else if (c.device == "power") {
    const bool close = c.command == "switch_on";
    switch_closed_[arg] = close;
    if (!close) unpower(switch_named(arg)->device);
  } else if (c.device == "telecom") {
    downlinking_ = c.command == "downlink";
  }
}

void Spacecraft::unpower(const std::string& device) {
  if (device == "camera") {
    camera_mode_ = "off";
    exposure_left_s_ = 0.0;
  } else if (device == "ips") {
    thrust_level_ = 0;
  } else if (device == "telecom") {
    downlinking_ = false;
  }
}

const BusSwitchSpec* Spacecraft::switch_named(const std::string& name) const {
  for (const BusSwitchSpec& s : spec_.power.switches)
    if (s.name == name) return &s;
  return nullptr;
}

bool Spacecraft::powered(const std::string& device) const {
  for (const BusSwitchSpec& s : spec_.power.switches)
    if (s.device == device && !switch_closed_.at(s.name)) return false;
  return true;
}

// --- Fault protection ---------------------------------------------------------------------------

void Spacecraft::commander_heard(const std::string& sign) {
  if (protection_.heard(time_s_))
    own_events_.push_back({"resumed", "safe mode ended by " + sign, time_s_});
}

void Spacecraft::enter_safe_mode() {
  const std::string reason = "no command or heartbeat of " + spec_.fault_protection.commander +
                             " for " + number(spec_.fault_protection.commander_timeout_s) + " s";
  std::vector<std::string> done;
  if (thrust_level_ > 0) {
    if (active(FaultKind::StuckOn, "ips")) {
      done.emplace_back("ips stuck on, still thrusting");
    } else {
      thrust_level_ = 0;
      done.emplace_back("ips to standby");
    }
  }
  if (camera_mode_ != "off") {
    if (camera_mode_ == "imaging" && active(FaultKind::StuckOn, "camera")) {
      done.emplace_back("camera stuck on, still imaging");
    } else {
      camera_mode_ = "off";
      exposure_left_s_ = 0.0;
      done.emplace_back("camera off");
    }
  }
  const std::string target = attitude_.turn_target();
  if (attitude_.hold())
    done.push_back("turn to " + target + " stopped, attitude held");
  else
    done.emplace_back("attitude held");
  protection_.safed(time_s_, reason);
  own_events_.push_back({"safed", reason + ": " + join(done), time_s_});
}

std::vector<SpacecraftEventRecord> Spacecraft::take_events() {
  std::vector<SpacecraftEventRecord> out;
  out.swap(own_events_);
  return out;
}

// --- Time ---------------------------------------------------------------------------------------

void Spacecraft::step(double dt_s) {
  if (protection_.due(time_s_)) enter_safe_mode();
  for (auto it = armed_.begin(); it != armed_.end();) {
    if (it->at_s && *it->at_s <= time_s_ + 1e-9) {
      FaultSpec f = std::move(*it);
      it = armed_.erase(it);
      const std::string trigger = "at " + number(*f.at_s) + " s";
      activate(std::move(f), trigger);
    } else {
      ++it;
    }
  }

  attitude_.step(dt_s, stuck_thrusters());

  if (camera_mode_ == "imaging" && exposure_left_s_ > 0.0) {
    exposure_left_s_ -= dt_s;
    if (exposure_left_s_ <= 1e-9) {
      exposure_left_s_ = 0.0;
      used_mb_ = std::min(spec_.storage.capacity_mb, used_mb_ + spec_.camera.image_mb);
      ++images_taken_;
      images_on_target_ += image_on_target_ ? 1 : 0;
      last_image_target_ = image_target_;
      // A camera stuck on stays imaging after its picture is taken.
      if (!active(FaultKind::StuckOn, "camera")) camera_mode_ = "ready";
    }
  }

  if (thrust_level_ > 0) thrust_time_s_ += dt_s;

  if (downlinking_) {
    const StationWindowSpec* w = window_at(time_s_);
    if (!w) {
      downlinking_ = false;  // the window closed: the station is out of view
    } else {
      const double sent = std::min(used_mb_, w->rate_kbps * dt_s / 8000.0);
      used_mb_ -= sent;
      downlinked_mb_ += sent;
    }
  }

  const double net_w = spec_.power.solar_array_w - load_w();
  battery_wh_ =
      std::clamp(battery_wh_ + net_w * dt_s / 3600.0, 0.0, spec_.power.battery_capacity_wh);

  time_s_ += dt_s;
  ++steps_;
}

const StationWindowSpec* Spacecraft::window_at(double t) const {
  for (const StationWindowSpec& w : spec_.telecom.windows)
    if (w.start_s <= t + 1e-9 && t < w.end_s - 1e-9) return &w;
  return nullptr;
}

// --- Power --------------------------------------------------------------------------------------

double Spacecraft::ips_power_w(int level) const {
  if (level <= 0) return 0.0;
  const IonEngineSpec& e = spec_.ion_engine;
  if (e.max_level == 1) return e.max_power_w;
  return e.min_power_w + (e.max_power_w - e.min_power_w) * (level - 1) / (e.max_level - 1);
}

double Spacecraft::camera_power_w() const {
  if (camera_mode_ == "imaging") return spec_.camera.imaging_power_w;
  if (camera_mode_ == "ready") return spec_.camera.ready_power_w;
  return 0.0;
}

double Spacecraft::load_w() const {
  return spec_.power.base_load_w + camera_power_w() + ips_power_w(thrust_level_) +
         (downlinking_ ? spec_.telecom.transmit_power_w : 0.0);
}

std::set<std::string> Spacecraft::stuck_thrusters() const {
  std::set<std::string> stuck;
  for (const ActiveFault& a : active_)
    if (a.spec.kind == FaultKind::StuckClosed) stuck.insert(a.spec.subject);
  return stuck;
}

// --- Telemetry ----------------------------------------------------------------------------------

std::string Spacecraft::reported_mode(const std::string& device) const {
  if (active(FaultKind::Failed, device)) return "failed";
  if (device == "adcs") return attitude_.turning() ? "turning" : "pointing";
  if (device == "ips") return thrust_level_ > 0 ? "thrusting" : "standby";
  if (device == "camera") return camera_mode_;
  if (device == "power") {
    const bool deficit = battery_wh_ <= 0.0 && load_w() > spec_.power.solar_array_w;
    return deficit ? "deficit" : "ok";
  }
  if (device == "telecom") return downlinking_ ? "downlinking" : "idle";
  if (device == "storage") return used_mb_ >= spec_.storage.capacity_mb - 1e-9 ? "full" : "ok";
  const auto& thrusters = spec_.attitude.thrusters;
  if (std::find(thrusters.begin(), thrusters.end(), device) != thrusters.end())
    return active(FaultKind::StuckClosed, device) ? "stuck_closed" : "ok";
  return "ok";  // electronics units
}

std::string Spacecraft::mode(const std::string& device) const {
  if (!std::binary_search(device_names_.begin(), device_names_.end(), device)) return "";
  return reported_mode(device);
}

std::map<std::string, double> Spacecraft::true_readings() const {
  std::map<std::string, double> r;
  for (const BusSwitchSpec& s : spec_.power.switches) {
    const double closed = switch_closed_.at(s.name) ? 1.0 : 0.0;
    r[s.name + "_status"] = closed;
    r[s.name + "_voltage_a"] = closed;
    r[s.name + "_voltage_b"] = closed;
  }
  r["battery_soc"] =
      spec_.power.battery_capacity_wh > 0.0 ? battery_wh_ / spec_.power.battery_capacity_wh : 0.0;
  r["solar_array_w"] = spec_.power.solar_array_w;
  r["load_w"] = load_w();
  r["ips_power_w"] = ips_power_w(thrust_level_);
  r["camera_power_w"] = camera_power_w();
  r["storage_used_mb"] = used_mb_;
  const StationWindowSpec* w = downlinking_ ? window_at(time_s_) : nullptr;
  r["downlink_rate_kbps"] = w && used_mb_ > 0.0 ? w->rate_kbps : 0.0;
  r["pointing_error_deg"] = attitude_.pointing_error_deg();
  r["turn_rate_deg_s"] = attitude_.last_rate_deg_s();
  return r;
}

std::optional<double> Spacecraft::reading(const std::string& sensor) const {
  for (const ActiveFault& a : active_)
    if (a.spec.kind == FaultKind::FalseSensor && a.spec.subject == sensor) return a.spec.value;
  const auto r = true_readings();
  const auto it = r.find(sensor);
  if (it == r.end()) return std::nullopt;
  return it->second;
}

msg::SpacecraftTelemetry Spacecraft::telemetry() const {
  msg::SpacecraftTelemetry t;
  t.spacecraft = spec_.name;
  for (const std::string& d : device_names_) {
    msg::DeviceReport report{d, reported_mode(d), "", "", -1};
    if (const auto it = confirmations_.find(d); it != confirmations_.end()) {
      report.confirmed_command = it->second.command;
      report.confirmed_command_id = it->second.id;
      report.confirmed_tick = it->second.tick;
    }
    t.devices.push_back(std::move(report));
  }
  for (const auto& [name, value] : true_readings()) {
    double shown = value;
    for (const ActiveFault& a : active_)
      if (a.spec.kind == FaultKind::FalseSensor && a.spec.subject == name) shown = a.spec.value;
    t.readings.push_back({name, shown});
  }

  const Eigen::Quaterniond& q = attitude_.orientation();
  t.attitude = {q.w(),
                q.x(),
                q.y(),
                q.z(),
                attitude_.pointing_target(),
                attitude_.turn_target(),
                attitude_.control_mode(),
                attitude_.last_rate_deg_s(),
                attitude_.remaining_deg()};
  t.propulsion = {static_cast<std::uint32_t>(thrust_level_), ips_power_w(thrust_level_),
                  thrust_time_s_};
  t.camera = {camera_power_w(), images_taken_, images_on_target_, last_image_target_};
  t.power = {spec_.power.solar_array_w, load_w(), *reading("battery_soc"), battery_wh_};
  const StationWindowSpec* w = window_at(time_s_);
  t.telecom = {w ? w->station : "", *reading("downlink_rate_kbps"), downlinked_mb_};
  t.storage = {used_mb_, spec_.storage.capacity_mb};
  t.commands_accepted = accepted_;
  t.commands_rejected = rejected_;
  t.fault_protection.safe_mode = protection_.safe_mode();
  t.fault_protection.reason = protection_.safe_mode() ? protection_.reason() : "";
  t.fault_protection.safed_at_ns =
      static_cast<std::int64_t>(std::llround(protection_.safed_at_s().value_or(0.0) * 1e9));
  t.fault_protection.safings = protection_.safings();
  t.fault_protection.commander_silent_s = protection_.silent_s(time_s_);
  t.fault_protection.commander_timeout_s = spec_.fault_protection.commander_timeout_s;
  return t;
}

}  // namespace autonomy::sim::spacecraft
