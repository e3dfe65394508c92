#include "executive_config.hpp"

#include <filesystem>
#include <set>

#include "common/config/text_format.hpp"
#include "idl/executive_config.pb.h"

namespace autonomy::executive {
namespace {

using configfile::FileError;
using configfile::Locator;
using configfile::Position;
namespace pbc = config;

FaultAction::Kind action_kind(pbc::Action a) {
  switch (a) {
    case pbc::RESET: return FaultAction::Kind::kReset;
    case pbc::IGNORE_SENSOR: return FaultAction::Kind::kIgnoreSensor;
    case pbc::SWITCH_CONTROL_MODE: return FaultAction::Kind::kSwitchControlMode;
    case pbc::STOP_COMMANDING: return FaultAction::Kind::kStopCommanding;
    default: return FaultAction::Kind::kAbortAndReplan;
  }
}

class Checker {
 public:
  Checker(std::string source, std::vector<FileError>& errors)
      : source_(std::move(source)), errors_(errors) {}

  void error(Position at, std::string message) {
    errors_.push_back({source_, at.line, at.column, std::move(message)});
  }

  std::string path(const std::string& relative, Position at, const char* what) {
    if (relative.empty()) {
      error(at, std::string(what) + " is missing");
      return {};
    }
    std::filesystem::path p(relative);
    if (p.is_relative() && source_.find(':') == std::string::npos)
      p = std::filesystem::path(source_).parent_path() / p;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec))
      error(at, std::string(what) + " '" + relative + "': no such file (" + p.string() + ")");
    return p.lexically_normal().string();
  }

  void rules(const pbc::ExecutiveConfig& f, const Locator& root, ExecutiveConfig& out) {
    CommandMap check;
    std::set<std::pair<std::string, std::string>> seen;
    for (int i = 0; i < f.commands_size(); ++i) {
      const pbc::CommandRule& r = f.commands(i);
      const Locator at = root.nested("commands", i);
      if (r.timeline().find('.') == std::string::npos) {
        error(r.timeline().empty() ? at.self() : at.at("timeline"),
              "command rule: timeline '" + r.timeline() + "' is not object.attribute");
        continue;
      }
      if (!seen.insert({r.timeline(), r.predicate()}).second) {
        error(at.at("predicate"), "command rule: a second rule for " + r.timeline() +
                                      " == " + r.predicate());
        continue;
      }
      if (r.confirm_timeout_s() < 0) {
        error(at.at("confirm_timeout_s"), "command rule: confirm_timeout_s must be >= 0");
        continue;
      }
      if (r.device().empty() && (!r.command().empty() || !r.end_mode().empty() || !r.end_command().empty())) {
        error(at.self(), "command rule for " + r.timeline() + " == " + r.predicate() +
                             ": command, end_mode and end_command need a device");
        continue;
      }
      CommandRule rule;
      rule.timeline = r.timeline();
      rule.predicate = r.predicate();
      rule.device = r.device();
      rule.command = r.command();
      rule.arguments.assign(r.arguments().begin(), r.arguments().end());
      rule.expect_mode = r.expect_mode();
      rule.end_mode = r.end_mode();
      rule.end_command = r.end_command();
      if (r.confirm_timeout_s() > 0) rule.confirm_timeout = static_cast<Time>(r.confirm_timeout_s() + 0.999);
      std::string why;
      if (!check.add(rule, &why)) {
        error(at.self(), "command rule for " + r.timeline() + " == " + r.predicate() + ": " + why);
        continue;
      }
      out.rules.push_back(std::move(rule));
    }
  }

  // Robots: devices named once, sites named once, and the rules for their devices use the
  // commands the robot link knows (go_to(site), report(site)).
  void robots(const pbc::ExecutiveConfig& f, const Locator& root, ExecutiveConfig& out) {
    std::set<std::string> devices;
    for (int i = 0; i < f.robots_size(); ++i) {
      const pbc::Robot& r = f.robots(i);
      const Locator at = root.nested("robots", i);
      RobotSpec spec{r.device(), r.robot_id().empty() ? r.device() : r.robot_id(), {},
                     r.tolerance(), r.radio_device(), r.base()};
      if (r.device().empty()) error(at.self(), "robot: device is needed");
      else if (!devices.insert(r.device()).second)
        error(at.at("device"), "robot: device '" + r.device() + "' is named twice");
      if (!r.radio_device().empty() && !devices.insert(r.radio_device()).second)
        error(at.at("radio_device"), "robot: device '" + r.radio_device() + "' is named twice");
      if (!r.radio_device().empty() && r.base().empty())
        error(at.at("radio_device"), "robot: radio_device needs base (the robot id reports go to)");
      if (r.tolerance() < 0) error(at.at("tolerance"), "robot: tolerance must be >= 0");
      if (r.sites_size() == 0) error(at.self(), "robot '" + r.device() + "': no sites to drive to");
      std::set<std::string> names;
      for (int k = 0; k < r.sites_size(); ++k) {
        const pbc::Site& s = r.sites(k);
        if (s.name().empty()) error(at.nested("sites", k).self(), "site: name is needed");
        else if (!names.insert(s.name()).second)
          error(at.nested("sites", k).at("name"), "site '" + s.name() + "' is named twice");
        spec.sites.push_back({s.name(), s.x(), s.y()});
      }
      out.robots.push_back(std::move(spec));
    }
    for (int i = 0; i < f.commands_size(); ++i) {
      const pbc::CommandRule& c = f.commands(i);
      if (c.command().empty()) continue;
      for (const RobotSpec& r : out.robots) {
        const char* needed = c.device() == r.device ? "go_to" : c.device() == r.radio_device ? "report" : nullptr;
        if (!needed) continue;
        if (c.command() != needed || c.arguments_size() != 1)
          error(root.nested("commands", i).at("command"),
                "command rule: robot device '" + c.device() + "' takes " + needed + "(site), not " +
                    c.command() + " with " + std::to_string(c.arguments_size()) + " arguments");
      }
    }
  }

  void safing(const pbc::Safing& f, const Locator& at, ExecutiveConfig& out) {
    for (int i = 0; i < f.commands_size(); ++i) {
      const pbc::DeviceCommand& c = f.commands(i);
      if (c.device().empty() || c.command().empty()) {
        error(at.nested("commands", i).self(), "safing command: device and command are needed");
        continue;
      }
      out.safing.push_back({c.device(), c.command(), {c.arguments().begin(), c.arguments().end()}});
    }
    for (int i = 0; i < f.values_size(); ++i) {
      const pbc::TimelineValue& v = f.values(i);
      if (v.timeline().find('.') == std::string::npos || v.predicate().empty()) {
        error(at.nested("values", i).self(),
              "safing value: timeline (object.attribute) and predicate are needed");
        continue;
      }
      out.safe_values.push_back({v.timeline(), v.predicate(), {v.parameters().begin(), v.parameters().end()}});
    }
  }

  void faults(const pbc::Faults& f, const Locator& at, FaultTableSpec& out) {
    auto samples = [&](int value, const char* field, int fallback) {
      if (value < 0) error(at.at(field), std::string(field) + " must be >= 0");
      return value > 0 ? value : fallback;
    };
    out.stuck_samples = samples(f.stuck_samples(), "stuck_samples", 2);
    out.max_resets = samples(f.max_resets(), "max_resets", 2);
    out.mode_samples = samples(f.mode_samples(), "mode_samples", 2);
    for (int i = 0; i < f.components_size(); ++i) {
      const pbc::Component& c = f.components(i);
      ComponentModel m;
      m.name = c.name();
      for (const pbc::Mode& mode : c.modes()) {
        ModeModel mm{mode.name(), mode.fault(), mode.cost(), mode.reports(), {}};
        for (const pbc::Prediction& p : mode.predictions())
          mm.predictions.push_back({p.observable(), p.value(), p.tolerance()});
        m.modes.push_back(std::move(mm));
      }
      for (const pbc::Dependency& d : c.depends_on())
        m.depends_on.push_back({d.component(), {d.modes().begin(), d.modes().end()}, d.otherwise()});
      out.components.push_back(std::move(m));
    }
    if (!out.components.empty()) {
      std::string why;
      if (!ModeIdentifier::create(out.components, {}, &why))
        error(at.at("components", 0), "mode identification: " + why);
    }
    for (int i = 0; i < f.mode_rules_size(); ++i) {
      const pbc::ModeRule& r = f.mode_rules(i);
      const Locator rl = at.nested("mode_rules", i);
      const ComponentModel* component = nullptr;
      for (const auto& c : out.components)
        if (c.name == r.component()) component = &c;
      if (!component) {
        error(rl.at("component"), "mode rule: component '" + r.component() + "' is not modelled");
        continue;
      }
      bool known = false;
      for (const auto& m : component->modes) known = known || m.name == r.mode();
      if (!known) {
        error(rl.at("mode"), "mode rule: component '" + r.component() + "' has no mode '" + r.mode() + "'");
        continue;
      }
      if (r.action() == pbc::SWITCH_CONTROL_MODE && (r.control_device().empty() || r.control_mode().empty())) {
        error(rl.self(), "mode rule: SWITCH_CONTROL_MODE needs control_device and control_mode");
        continue;
      }
      out.mode_rules.push_back({r.component(), r.mode(), action_kind(r.action()), r.control_device(), r.control_mode()});
    }
    for (int i = 0; i < f.sensors_size(); ++i) {
      const pbc::RedundantSensor& s = f.sensors(i);
      if (s.sensor().empty() || s.evidence().empty()) {
        error(at.nested("sensors", i).self(), "redundant sensor: sensor and evidence are needed");
        continue;
      }
      out.sensors.push_back({s.sensor(), {s.evidence().begin(), s.evidence().end()},
                             s.tolerance() > 0 ? s.tolerance() : 0.5, s.samples() > 0 ? s.samples() : 3});
    }
    for (int i = 0; i < f.actuators_size(); ++i) {
      const pbc::ActuatorFallback& a = f.actuators(i);
      if (a.actuator().empty() || a.control_device().empty() || a.fallback_mode().empty()) {
        error(at.nested("actuators", i).self(),
              "actuator fallback: actuator, control_device and fallback_mode are needed");
        continue;
      }
      out.actuators.push_back({a.actuator(), a.control_device(), a.fallback_mode()});
    }
  }

 private:
  std::string source_;
  std::vector<FileError>& errors_;
};

}  // namespace

const RobotSpec::Site* RobotSpec::site(const std::string& name) const {
  for (const Site& s : sites)
    if (s.name == name) return &s;
  return nullptr;
}

CommandMap ExecutiveConfig::command_map() const {
  CommandMap map;
  std::string ignored;
  for (const CommandRule& r : rules) map.add(r, &ignored);
  return map;
}

std::vector<std::unique_ptr<FaultResponse>> ExecutiveConfig::fault_table() const {
  std::vector<std::unique_ptr<FaultResponse>> table;
  table.push_back(std::make_unique<StuckDeviceResponse>(faults.stuck_samples));
  table.push_back(std::make_unique<ResetUnitResponse>(faults.max_resets));
  if (!faults.components.empty()) {
    std::string ignored;
    if (auto identifier = ModeIdentifier::create(faults.components, {}, &ignored))
      table.push_back(std::make_unique<ModeIdentificationResponse>(std::move(*identifier),
                                                                   faults.mode_rules, faults.mode_samples));
  }
  if (!faults.sensors.empty()) table.push_back(std::make_unique<FalseSensorResponse>(faults.sensors));
  if (!faults.actuators.empty()) table.push_back(std::make_unique<ActuatorStuckResponse>(faults.actuators));
  table.push_back(std::make_unique<UnconfirmedCommandResponse>());
  return table;
}

std::vector<std::string> ExecutiveConfig::devices_of(const std::string& timeline) const {
  std::vector<std::string> devices;
  for (const CommandRule& r : rules)
    if (r.timeline == timeline && !r.device.empty() && !r.command.empty()) devices.push_back(r.device);
  return devices;
}

std::optional<ExecutiveConfig> parse_executive_config(const std::string& text,
                                                      const std::string& source,
                                                      std::vector<FileError>& errors) {
  pbc::ExecutiveConfig file;
  Locator::ParseInfoTree tree;
  if (!configfile::parse_text_format(text, source, file, tree, errors)) return std::nullopt;
  const std::size_t before = errors.size();
  Checker check(source, errors);
  const Locator root(&tree, pbc::ExecutiveConfig::descriptor(), {1, 1});
  ExecutiveConfig out;
  out.source = source;
  out.name = file.name();
  out.model_path = check.path(file.model(), root.at("model"), "model");
  out.problem_path = check.path(file.problem(), root.at("problem"), "problem");
  if (file.commands_size() == 0) check.error(root.self(), "no command rules: nothing would be commanded");
  check.rules(file, root, out);
  check.safing(file.safing(), root.nested("safing"), out);
  check.robots(file, root, out);
  check.faults(file.faults(), root.nested("faults"), out.faults);
  if (file.horizon_s() < 0) check.error(root.at("horizon_s"), "horizon_s must be >= 0");
  if (file.request_lead_s() < 0) check.error(root.at("request_lead_s"), "request_lead_s must be >= 0");
  out.horizon_s = file.horizon_s();
  if (file.request_lead_s() > 0) out.request_lead_s = file.request_lead_s();
  if (out.horizon_s > 0 && out.request_lead_s >= out.horizon_s)
    check.error(root.at("request_lead_s"), "request_lead_s must be shorter than horizon_s");
  if (file.planner_budget_ms() < 0) check.error(root.at("planner_budget_ms"), "planner_budget_ms must be >= 0");
  out.planner_engine = file.planner_engine();
  out.planner_budget_ms = file.planner_budget_ms();
  if (!file.optional_engine().empty()) out.optional_engine = file.optional_engine();
  if (errors.size() != before) {
    configfile::sort_by_position(errors);
    return std::nullopt;
  }
  return out;
}

std::optional<ExecutiveConfig> load_executive_config(const std::string& path,
                                                     std::vector<FileError>& errors) {
  auto text = configfile::read_text_file(path, errors);
  if (!text) return std::nullopt;
  return parse_executive_config(*text, path, errors);
}

}  // namespace autonomy::executive
