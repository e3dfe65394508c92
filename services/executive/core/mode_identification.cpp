#include "mode_identification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace autonomy::executive {
namespace {

constexpr double kTie = 1e-9;

bool is_otherwise_mode(const ComponentModel& c, const std::string& mode) {
  for (const Dependency& d : c.depends_on)
    if (d.otherwise == mode) return true;
  return false;
}

const ModeModel* find_mode(const ComponentModel& c, const std::string& name) {
  for (const ModeModel& m : c.modes)
    if (m.name == name) return &m;
  return nullptr;
}

// Depth-first branch and bound over the components in dependency order. The cost of a partial
// assignment only grows (modes add their cost, a reading once contradicted stays charged), so
// it bounds every completion.
class Search {
 public:
  Search(const std::vector<ComponentModel>& components, const ModeCosts& costs,
         const std::map<std::string, std::string>& expected, const Observations& seen)
      : components_(components), costs_(costs), expected_(expected), seen_(seen) {
    for (std::size_t i = 0; i < components.size(); ++i) index_[components[i].name] = i;
    chosen_.assign(components.size(), nullptr);
  }

  Diagnosis run() {
    descend(0, 0.0);
    Diagnosis d;
    d.cost = best_cost_;
    d.ambiguous = best_count_ > 1;
    d.assignments_tried = tried_;
    for (std::size_t i = 0; i < components_.size(); ++i) {
      const ModeModel* m = best_[i];
      d.modes[components_[i].name] = m->name;
      if (m->fault) d.faults.push_back(components_[i].name + "=" + m->name);
    }
    d.false_sensors.assign(best_false_.begin(), best_false_.end());
    return d;
  }

 private:
  // The readings a mode contradicts (name of the reading, or "mode:<device>" for a report).
  std::vector<std::string> contradicted(const ComponentModel& c, const ModeModel& m) const {
    std::vector<std::string> out;
    if (!m.reports.empty()) {
      auto r = seen_.device_modes.find(c.name);
      if (r != seen_.device_modes.end() && r->second != m.reports) out.push_back("mode:" + c.name);
    }
    for (const Prediction& p : m.predictions) {
      auto r = seen_.readings.find(p.observable);
      if (r != seen_.readings.end() && std::fabs(r->second - p.value) > p.tolerance)
        out.push_back(p.observable);
    }
    return out;
  }

  std::vector<std::pair<const ModeModel*, double>> candidates(std::size_t i) const {
    const ComponentModel& c = components_[i];
    for (const Dependency& d : c.depends_on) {
      const ModeModel* other = chosen_[index_.at(d.component)];
      if (std::find(d.modes.begin(), d.modes.end(), other->name) == d.modes.end())
        return {{find_mode(c, d.otherwise), 0.0}};
    }
    auto e = expected_.find(c.name);
    std::vector<std::pair<const ModeModel*, double>> out;
    for (const ModeModel& m : c.modes) {
      if (is_otherwise_mode(c, m.name)) continue;
      double cost = m.fault ? m.cost
                    : e == expected_.end() || e->second == m.name ? 0.0
                                                                   : costs_.unexpected_mode;
      out.push_back({&m, cost});
    }
    std::stable_sort(out.begin(), out.end(),
                     [](const auto& a, const auto& b) { return a.second < b.second; });
    return out;
  }

  void descend(std::size_t i, double cost) {
    if (cost > best_cost_ + kTie) return;
    if (i == components_.size()) {
      ++tried_;
      if (cost < best_cost_ - kTie) {
        best_cost_ = cost;
        best_count_ = 1;
        best_ = chosen_;
        best_false_ = charged_names();
      } else {
        ++best_count_;
      }
      return;
    }
    for (const auto& [mode, mode_cost] : candidates(i)) {
      chosen_[i] = mode;
      double added = mode_cost;
      const std::vector<std::string> against = contradicted(components_[i], *mode);
      for (const std::string& r : against)
        if (charged_[r]++ == 0) added += costs_.false_sensor;  // a reading is charged once
      descend(i + 1, cost + added);
      for (const std::string& r : against) --charged_[r];
    }
    chosen_[i] = nullptr;
  }

  std::set<std::string> charged_names() const {
    std::set<std::string> out;
    for (const auto& [name, count] : charged_)
      if (count > 0) out.insert(name);
    return out;
  }

  const std::vector<ComponentModel>& components_;
  const ModeCosts& costs_;
  const std::map<std::string, std::string>& expected_;
  const Observations& seen_;
  std::map<std::string, std::size_t> index_;
  std::vector<const ModeModel*> chosen_, best_;
  std::map<std::string, int> charged_;
  std::set<std::string> best_false_;
  double best_cost_ = std::numeric_limits<double>::infinity();
  std::size_t best_count_ = 0, tried_ = 0;
};

}  // namespace

std::optional<ModeIdentifier> ModeIdentifier::create(std::vector<ComponentModel> components,
                                                     ModeCosts costs, std::string* error) {
  auto fail = [&](std::string why) {
    if (error) *error = std::move(why);
    return std::nullopt;
  };
  std::map<std::string, const ComponentModel*> by_name;
  for (const ComponentModel& c : components) {
    if (c.modes.empty()) return fail("component '" + c.name + "' has no modes");
    if (!by_name.emplace(c.name, &c).second) return fail("component '" + c.name + "' twice");
  }
  for (const ComponentModel& c : components)
    for (const Dependency& d : c.depends_on) {
      auto other = by_name.find(d.component);
      if (other == by_name.end())
        return fail("component '" + c.name + "' depends on unknown component '" + d.component +
                    "'");
      for (const std::string& m : d.modes)
        if (!find_mode(*other->second, m))
          return fail("component '" + c.name + "' depends on unknown mode '" + m + "' of '" +
                      d.component + "'");
      if (!find_mode(c, d.otherwise))
        return fail("component '" + c.name + "' has no mode '" + d.otherwise +
                    "' for when its dependency on '" + d.component + "' is unmet");
    }
  // Dependency order (Kahn); what is left over depends in a cycle.
  std::vector<ComponentModel> ordered;
  std::set<std::string> placed;
  while (ordered.size() < components.size()) {
    bool progress = false;
    for (const ComponentModel& c : components) {
      if (placed.count(c.name)) continue;
      bool ready = std::all_of(c.depends_on.begin(), c.depends_on.end(),
                               [&](const Dependency& d) { return placed.count(d.component) > 0; });
      if (!ready) continue;
      placed.insert(c.name);
      ordered.push_back(c);
      progress = true;
    }
    if (!progress) {
      for (const ComponentModel& c : components)
        if (!placed.count(c.name)) return fail("component '" + c.name + "' depends in a cycle");
    }
  }
  return ModeIdentifier(std::move(ordered), costs);
}

Diagnosis ModeIdentifier::identify(const std::map<std::string, std::string>& expected,
                                   const Observations& seen) const {
  return Search(components_, costs_, expected, seen).run();
}

std::vector<FaultAction> ModeIdentificationResponse::assess(const Observations& seen,
                                                            const PlanState& plan) {
  Diagnosis d = identifier_.identify(plan.expected_modes, seen);
  bool same = d.modes == last_.modes && d.false_sensors == last_.false_sensors;
  same_for_ = same ? same_for_ + 1 : 1;
  last_ = d;
  std::vector<FaultAction> actions;
  if (d.ambiguous || same_for_ < samples_) return actions;
  auto explain = [&] {
    std::string text = "cost " + std::to_string(d.cost).substr(0, 4) + ":";
    for (const std::string& f : d.faults) text += " " + f;
    for (const std::string& s : d.false_sensors) text += " false " + s;
    return text;
  };
  for (const std::string& s : d.false_sensors) {
    if (acted_["sensor:" + s]) continue;
    acted_["sensor:" + s] = true;
    actions.push_back({FaultAction::Kind::kIgnoreSensor, s, "", "",
                       s + " contradicts the most consistent modes (" + explain() + ")"});
  }
  for (const ModeResponseRule& r : rules_) {
    auto m = d.modes.find(r.component);
    std::string key = r.component + "=" + r.mode;
    if (m == d.modes.end() || m->second != r.mode) {
      acted_[key] = false;  // recovered (a reset worked): a later recurrence is answered again
      continue;
    }
    if (acted_[key]) continue;
    acted_[key] = true;
    actions.push_back({r.action, r.component, r.control_mode, r.control_device,
                       r.component + " identified " + r.mode + " (" + explain() + ")"});
  }
  return actions;
}

}  // namespace autonomy::executive
