#include "simulator/scenario/spacecraft_section.hpp"

#include "idl/scenario.pb.h"
#include "simulator/core/number_format.hpp"
#include "simulator/spacecraft/spacecraft.hpp"

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace autonomy::sim {
namespace {

using configfile::Locator;
using configfile::Position;
namespace sc = spacecraft;

const std::set<std::string> kFixedDevices = {"adcs",  "ips",     "camera",
                                             "power", "telecom", "storage"};

class SectionChecker {
 public:
  SectionChecker(const std::string& source, std::vector<ScenarioError>& errors)
      : source_(source), errors_(errors) {}

  std::optional<sc::SpacecraftSpec> check(const config::Spacecraft& f, const Locator& at) {
    const std::size_t before = errors_.size();
    sc::SpacecraftSpec spec;
    spec.name = f.name();
    if (spec.name.empty()) error(at.self(), "spacecraft: name is missing");
    targets(f, at, spec);
    attitude(f, at, spec);
    ion_engine(f, at.nested("ion_engine"), spec.ion_engine);
    camera(f, at.nested("camera"), spec.camera);
    power(f, at.nested("power"), spec.power);
    telecom(f, at.nested("telecom"), spec.telecom);
    storage(f, at.nested("storage"), spec.storage);
    electronics(f, at, spec);
    fault_protection(f, at, spec);
    if (errors_.size() != before) return std::nullopt;  // faults refer to checked devices
    faults(f, at, spec);
    if (errors_.size() != before) return std::nullopt;
    try {  // the core's own checks are the backstop
      sc::Spacecraft probe(spec);
    } catch (const std::invalid_argument& e) {
      error(at.self(), e.what());
      return std::nullopt;
    }
    return spec;
  }

 private:
  void error(Position p, std::string message) {
    errors_.push_back({source_, p.line, p.column, std::move(message)});
  }

  // An explicit value checked against `ok`; an absent one takes `fallback`.
  double value(bool present, double v, double fallback, bool ok, const std::string& what,
               const std::string& rule, Position p) {
    if (!present) return fallback;
    if (!std::isfinite(v) || !ok)
      error(p, what + " must be " + rule + " (got " + format_number(v) + ")");
    return v;
  }

  void unique(std::map<std::string, int>& seen, const std::string& name, const std::string& what,
              Position p) {
    if (const auto [it, fresh] = seen.emplace(name, p.line); !fresh)
      error(p, "duplicate " + what + " '" + name + "' (first defined at line " +
                   std::to_string(it->second) + ")");
  }

  void targets(const config::Spacecraft& f, const Locator& at, sc::SpacecraftSpec& spec) {
    if (f.targets_size() == 0) error(at.self(), "spacecraft: at least one target is needed");
    std::map<std::string, int> seen;
    for (int i = 0; i < f.targets_size(); ++i) {
      const config::SpacecraftTarget& t = f.targets(i);
      const Locator tl = at.nested("targets", i);
      if (t.name().empty()) {
        error(tl.self(), "target " + std::to_string(i) + ": name is missing");
        continue;
      }
      unique(seen, t.name(), "target", tl.at("name"));
      const Eigen::Vector3d d(t.direction().x(), t.direction().y(), t.direction().z());
      if (!t.has_direction() || !d.allFinite() || d.norm() < 1e-12)
        error(t.has_direction() ? tl.at("direction") : tl.self(),
              "target '" + t.name() + "': direction must be a finite non-zero vector");
      spec.targets.push_back({t.name(), d});
      target_names_.insert(t.name());
    }
  }

  void attitude(const config::Spacecraft& f, const Locator& root, sc::SpacecraftSpec& spec) {
    if (!f.has_attitude()) {
      error(root.self(), "spacecraft: attitude is missing");
      return;
    }
    const config::Attitude& a = f.attitude();
    const Locator at = root.nested("attitude");
    sc::AttitudeSpec& out = spec.attitude;
    std::map<std::string, int> seen;
    for (int i = 0; i < a.thrusters_size(); ++i) {
      const std::string& t = a.thrusters(i);
      if (t.empty() || kFixedDevices.count(t)) {
        error(at.at("thrusters", i), "thruster '" + t + "': a thruster needs a name of its own");
        continue;
      }
      unique(seen, t, "thruster", at.at("thrusters", i));
      out.thrusters.push_back(t);
      devices_.insert(t);
    }
    std::map<std::string, int> modes;
    if (a.modes_size() == 0) error(at.self(), "attitude: at least one control mode is needed");
    for (int i = 0; i < a.modes_size(); ++i) {
      const config::ControlMode& m = a.modes(i);
      const Locator ml = at.nested("modes", i);
      if (m.name().empty())
        error(ml.self(), "control mode " + std::to_string(i) + ": name is missing");
      unique(modes, m.name(), "control mode", ml.at("name"));
      sc::ControlModeSpec mode{m.name(), {}, m.max_rate_deg_s()};
      if (!(std::isfinite(m.max_rate_deg_s()) && m.max_rate_deg_s() > 0))
        error(ml.at("max_rate_deg_s"), "control mode '" + m.name() +
                                           "': max_rate_deg_s must be positive (got " +
                                           format_number(m.max_rate_deg_s()) + ")");
      for (int k = 0; k < m.actuators_size(); ++k) {
        if (!seen.count(m.actuators(k)))
          error(ml.at("actuators", k), "control mode '" + m.name() + "': actuator '" +
                                           m.actuators(k) + "' is not one of attitude.thrusters");
        mode.actuators.push_back(m.actuators(k));
      }
      out.modes.push_back(std::move(mode));
    }
    out.initial_target = a.initial_target();
    if (!target_names_.count(a.initial_target()))
      error(a.initial_target().empty() ? at.self() : at.at("initial_target"),
            "attitude: initial_target '" + a.initial_target() + "' is not a target");
    out.control_mode = a.control_mode();
    if (!modes.count(a.control_mode()))
      error(a.control_mode().empty() ? at.self() : at.at("control_mode"),
            "attitude: control_mode '" + a.control_mode() + "' is not one of its modes");
    out.pointing_tolerance_deg =
        value(a.has_pointing_tolerance_deg(), a.pointing_tolerance_deg(),
              out.pointing_tolerance_deg, a.pointing_tolerance_deg() > 0,
              "attitude: pointing_tolerance_deg", "positive", at.at("pointing_tolerance_deg"));
  }

  void ion_engine(const config::Spacecraft& f, const Locator& at, sc::IonEngineSpec& out) {
    const config::IonEngine& e = f.ion_engine();
    if (e.has_max_level()) {
      if (e.max_level() < 1 || e.max_level() > 1000)
        error(at.at("max_level"), "ion_engine: max_level must be in 1..1000 (got " +
                                      std::to_string(e.max_level()) + ")");
      out.max_level = static_cast<int>(e.max_level());
    }
    out.min_power_w =
        value(e.has_min_power_w(), e.min_power_w(), out.min_power_w, e.min_power_w() >= 0,
              "ion_engine: min_power_w", ">= 0", at.at("min_power_w"));
    out.max_power_w = value(e.has_max_power_w(), e.max_power_w(), out.max_power_w,
                            e.max_power_w() >= out.min_power_w, "ion_engine: max_power_w",
                            ">= min_power_w", at.at("max_power_w"));
    if (!e.has_max_power_w() && out.max_power_w < out.min_power_w)
      error(at.at("min_power_w"), "ion_engine: min_power_w must be <= max_power_w (" +
                                      format_number(out.max_power_w) + ")");
  }

  void camera(const config::Spacecraft& f, const Locator& at, sc::CameraSpec& out) {
    const config::SpacecraftCamera& c = f.camera();
    if (!c.initial_mode().empty()) {
      if (c.initial_mode() != "off" && c.initial_mode() != "ready")
        error(at.at("initial_mode"), "camera: initial_mode must be \"off\" or \"ready\" (got \"" +
                                         c.initial_mode() + "\")");
      out.initial_mode = c.initial_mode();
    }
    out.ready_power_w =
        value(c.has_ready_power_w(), c.ready_power_w(), out.ready_power_w, c.ready_power_w() >= 0,
              "camera: ready_power_w", ">= 0", at.at("ready_power_w"));
    out.imaging_power_w = value(c.has_imaging_power_w(), c.imaging_power_w(), out.imaging_power_w,
                                c.imaging_power_w() >= 0, "camera: imaging_power_w", ">= 0",
                                at.at("imaging_power_w"));
    out.exposure_s = value(c.has_exposure_s(), c.exposure_s(), out.exposure_s, c.exposure_s() > 0,
                           "camera: exposure_s", "positive", at.at("exposure_s"));
    out.image_mb = value(c.has_image_mb(), c.image_mb(), out.image_mb, c.image_mb() >= 0,
                         "camera: image_mb", ">= 0", at.at("image_mb"));
  }

  void power(const config::Spacecraft& f, const Locator& at, sc::PowerSpec& out) {
    const config::SpacecraftPower& p = f.power();
    out.solar_array_w =
        value(p.has_solar_array_w(), p.solar_array_w(), out.solar_array_w, p.solar_array_w() >= 0,
              "power: solar_array_w", ">= 0", at.at("solar_array_w"));
    out.battery_capacity_wh =
        value(p.has_battery_capacity_wh(), p.battery_capacity_wh(), out.battery_capacity_wh,
              p.battery_capacity_wh() > 0, "power: battery_capacity_wh", "positive",
              at.at("battery_capacity_wh"));
    out.battery_soc = value(p.has_battery_soc(), p.battery_soc(), out.battery_soc,
                            p.battery_soc() >= 0 && p.battery_soc() <= 1, "power: battery_soc",
                            "in 0..1", at.at("battery_soc"));
    out.base_load_w =
        value(p.has_base_load_w(), p.base_load_w(), out.base_load_w, p.base_load_w() >= 0,
              "power: base_load_w", ">= 0", at.at("base_load_w"));
    out.max_discharge_w =
        value(p.has_max_discharge_w(), p.max_discharge_w(), out.max_discharge_w,
              p.max_discharge_w() >= 0, "power: max_discharge_w", ">= 0", at.at("max_discharge_w"));
    std::map<std::string, int> seen, fed;
    for (int i = 0; i < p.switches_size(); ++i) {
      const config::BusSwitch& s = p.switches(i);
      const Locator sl = at.nested("switches", i);
      if (s.name().empty())
        error(sl.self(), "bus switch " + std::to_string(i) + ": name is missing");
      unique(seen, s.name(), "bus switch", sl.at("name"));
      if (s.device() != "camera" && s.device() != "ips" && s.device() != "telecom")
        error(s.device().empty() ? sl.self() : sl.at("device"),
              "bus switch '" + s.name() + "': device must be camera, ips or telecom (got \"" +
                  s.device() + "\")");
      else
        unique(fed, s.device(), "switch for device", sl.at("device"));
      out.switches.push_back({s.name(), s.device(), !s.has_closed() || s.closed()});
    }
  }

  void telecom(const config::Spacecraft& f, const Locator& at, sc::TelecomSpec& out) {
    const config::Telecom& t = f.telecom();
    out.transmit_power_w = value(t.has_transmit_power_w(), t.transmit_power_w(),
                                 out.transmit_power_w, t.transmit_power_w() >= 0,
                                 "telecom: transmit_power_w", ">= 0", at.at("transmit_power_w"));
    double previous_end = 0;
    for (int i = 0; i < t.windows_size(); ++i) {
      const config::StationWindow& w = t.windows(i);
      const Locator wl = at.nested("windows", i);
      const std::string who =
          "window " + std::to_string(i) + (w.station().empty() ? "" : " (" + w.station() + ")");
      if (w.station().empty()) error(wl.self(), who + ": station is missing");
      if (!(std::isfinite(w.start_s()) && w.start_s() >= 0))
        error(wl.at("start_s"),
              who + ": start_s must be >= 0 (got " + format_number(w.start_s()) + ")");
      else if (w.start_s() < previous_end)
        error(wl.at("start_s"), who + ": starts at " + format_number(w.start_s()) +
                                    " s, before the previous window ends (" +
                                    format_number(previous_end) + " s)");
      if (!(std::isfinite(w.end_s()) && w.end_s() > w.start_s()))
        error(wl.at("end_s"),
              who + ": end_s must be after start_s (got " + format_number(w.end_s()) + ")");
      if (!(std::isfinite(w.rate_kbps()) && w.rate_kbps() > 0))
        error(wl.at("rate_kbps"),
              who + ": rate_kbps must be positive (got " + format_number(w.rate_kbps()) + ")");
      previous_end = std::max(previous_end, w.end_s());
      out.windows.push_back({w.station(), w.start_s(), w.end_s(), w.rate_kbps()});
    }
  }

  void storage(const config::Spacecraft& f, const Locator& at, sc::StorageSpec& out) {
    const config::DataStorage& s = f.storage();
    out.capacity_mb =
        value(s.has_capacity_mb(), s.capacity_mb(), out.capacity_mb, s.capacity_mb() > 0,
              "storage: capacity_mb", "positive", at.at("capacity_mb"));
    out.used_mb = s.used_mb();
    if (!(std::isfinite(s.used_mb()) && s.used_mb() >= 0 && s.used_mb() <= out.capacity_mb))
      error(at.at("used_mb"), "storage: used_mb must be in 0.." + format_number(out.capacity_mb) +
                                  " (got " + format_number(s.used_mb()) + ")");
  }

  void electronics(const config::Spacecraft& f, const Locator& at, sc::SpacecraftSpec& spec) {
    for (int i = 0; i < f.electronics_size(); ++i) {
      const config::ElectronicsUnit& u = f.electronics(i);
      const Locator ul = at.nested("electronics", i);
      if (u.name().empty() || kFixedDevices.count(u.name()) || devices_.count(u.name())) {
        error(u.name().empty() ? ul.self() : ul.at("name"),
              "electronics unit '" + u.name() + "': a unit needs a device name of its own");
        continue;
      }
      devices_.insert(u.name());
      sc::ElectronicsSpec unit{u.name(), {}};
      for (int k = 0; k < u.devices_size(); ++k) {
        if (!kFixedDevices.count(u.devices(k)))
          error(ul.at("devices", k), "electronics unit '" + u.name() + "': '" + u.devices(k) +
                                         "' is not adcs, ips, camera, power, telecom or storage");
        unit.devices.push_back(u.devices(k));
      }
      spec.electronics.push_back(std::move(unit));
    }
  }

  void fault_protection(const config::Spacecraft& f, const Locator& root, sc::SpacecraftSpec& spec) {
    const config::FaultProtection& p = f.fault_protection();
    const Locator at = root.nested("fault_protection");
    sc::FaultProtectionSpec& out = spec.fault_protection;
    out.commander_timeout_s =
        value(p.has_commander_timeout_s(), p.commander_timeout_s(), out.commander_timeout_s,
              p.commander_timeout_s() >= 0, "fault_protection: commander_timeout_s",
              ">= 0 (0: off)", at.at("commander_timeout_s"));
    if (p.has_commander()) {
      out.commander = p.commander();
      if (out.commander.empty() || out.commander.size() > 64)
        error(at.at("commander"), "fault_protection: commander must be a service name of 1..64 "
                                  "characters");
    }
    if (f.has_command_queue_limit()) {
      spec.command_queue_limit = f.command_queue_limit();
      if (spec.command_queue_limit < 1)
        error(root.at("command_queue_limit"), "command_queue_limit must be at least 1 (got 0)");
    }
  }

  void faults(const config::Spacecraft& f, const Locator& at, sc::SpacecraftSpec& spec) {
    const sc::Spacecraft probe(spec);  // the devices and readings faults may name
    std::map<std::string, int> seen;
    for (int i = 0; i < f.faults_size(); ++i) {
      const config::SpacecraftFault& x = f.faults(i);
      const Locator fl = at.nested("faults", i);
      if (x.id().empty()) {
        error(fl.self(), "fault " + std::to_string(i) + ": id is missing");
        continue;
      }
      unique(seen, x.id(), "fault", fl.at("id"));
      sc::FaultSpec fault;
      fault.id = x.id();
      fault.subject = x.subject();
      fault.value = x.value();
      fault.reset_cures = !x.has_reset_cures() || x.reset_cures();
      switch (x.kind()) {
        case config::STUCK_ON:
          fault.kind = sc::FaultKind::StuckOn;
          break;
        case config::FAILED:
          fault.kind = sc::FaultKind::Failed;
          break;
        case config::FALSE_SENSOR:
          fault.kind = sc::FaultKind::FalseSensor;
          break;
        case config::STUCK_CLOSED:
          fault.kind = sc::FaultKind::StuckClosed;
          break;
        case config::NEVER_CONFIRMED:
          fault.kind = sc::FaultKind::NeverConfirmed;
          break;
        default:
          error(fl.self(), "fault '" + x.id() +
                               "': kind is missing (STUCK_ON, FAILED, FALSE_SENSOR, STUCK_CLOSED, "
                               "NEVER_CONFIRMED)");
          continue;
      }
      if (x.trigger_case() == config::SpacecraftFault::kAtS) fault.at_s = x.at_s();
      if (x.trigger_case() == config::SpacecraftFault::kOnCommand)
        fault.on_command = x.on_command();
      if (auto problem = probe.fault_problem(fault)) {
        const char* field = x.trigger_case() == config::SpacecraftFault::kOnCommand &&
                                    problem->find("on_command") != std::string::npos
                                ? "on_command"
                            : problem->find("at_s") != std::string::npos ? "at_s"
                                                                         : "subject";
        error(fl.at(field), *problem);
        continue;
      }
      spec.faults.push_back(std::move(fault));
    }
  }

  const std::string& source_;
  std::vector<ScenarioError>& errors_;
  std::set<std::string> target_names_;
  std::set<std::string> devices_;  // thrusters and units
};

}  // namespace

std::optional<spacecraft::SpacecraftSpec> check_spacecraft_section(
    const config::Spacecraft& file, const Locator& at, const std::string& source,
    std::vector<ScenarioError>& errors) {
  return SectionChecker(source, errors).check(file, at);
}

}  // namespace autonomy::sim
