#include "services/behavior/core/mission/mission_loader.hpp"

#include "idl/mission.pb.h"

#include "common/config/text_format.hpp"

#include <google/protobuf/text_format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

namespace autonomy::behavior {

namespace {

namespace pb = google::protobuf;
using ParseInfoTree = pb::TextFormat::ParseInfoTree;

using configfile::Locator;
using configfile::Position;

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

class MissionChecker {
 public:
  MissionChecker(const std::string& source, std::vector<MissionError>& errors)
      : source_(source), errors_(errors) {}

  MissionSpec check(const config::Mission& file, const ParseInfoTree& tree) {
    const Locator root(&tree, config::Mission::descriptor(), Position{});
    MissionSpec out;
    out.name = file.name();
    out.robot = file.robot();
    teammates(file, root, out);
    out.schemas = schemas(file.schemas(), root.nested("schemas"));
    layers(file, root, out);
    plan_sets(file, root, out);
    states(file, root, out);
    out.initial_state = file.initial_state();
    if (file.initial_state().empty()) {
      error(root.self(), "initial_state is missing");
    } else if (state_lines_.count(file.initial_state()) == 0) {
      error(root.at("initial_state"), "initial_state names unknown state " + file.initial_state());
    }
    return out;
  }

 private:
  void error(Position at, std::string message) {
    errors_.push_back({source_, at.line, at.column, std::move(message)});
  }

  // Explicit values must be positive and finite; absent ones take `fallback`.
  double positive(bool present, double value, double fallback, const std::string& what, Position at) {
    if (!present) return fallback;
    if (!(std::isfinite(value) && value > 0.0)) {
      error(at, what + " must be positive (got " + number(value) + ")");
    }
    return value;
  }

  double non_negative(bool present, double value, double fallback, const std::string& what,
                      Position at) {
    if (!present) return fallback;
    if (!(std::isfinite(value) && value >= 0.0)) {
      error(at, what + " must not be negative (got " + number(value) + ")");
    }
    return value;
  }

  // Records a name's first line; reports a duplicate. Returns false for empty or duplicate names.
  bool unique(std::map<std::string, int>& seen, const std::string& name, const std::string& what,
              Position at) {
    if (name.empty()) {
      error(at, what + " name is empty");
      return false;
    }
    const auto [it, fresh] = seen.emplace(name, at.line);
    if (!fresh) {
      error(at, "duplicate " + what + " name " + name + " (first defined at line " +
                    std::to_string(it->second) + ")");
    }
    return fresh;
  }

  void teammates(const config::Mission& file, const Locator& root, MissionSpec& out) {
    std::map<std::string, int> seen;
    for (int i = 0; i < file.teammates_size(); ++i) {
      if (unique(seen, file.teammates(i), "teammate", root.at("teammates", i))) {
        out.teammates.push_back(file.teammates(i));
      }
    }
  }

  SchemaParameters schemas(const config::SchemaParameters& s, const Locator& at) {
    const SchemaParameters d;
    SchemaParameters p;
    p.slowdown_radius_m = positive(s.has_slowdown_radius(), s.slowdown_radius(), d.slowdown_radius_m,
                                   "schemas: slowdown_radius", at.at("slowdown_radius"));
    p.sphere_of_influence_m =
        positive(s.has_sphere_of_influence(), s.sphere_of_influence(), d.sphere_of_influence_m,
                 "schemas: sphere_of_influence", at.at("sphere_of_influence"));
    p.safety_margin_m = non_negative(s.has_safety_margin(), s.safety_margin(), d.safety_margin_m,
                                     "schemas: safety_margin", at.at("safety_margin"));
    if (finite({p.safety_margin_m, p.sphere_of_influence_m}) &&
        p.safety_margin_m >= p.sphere_of_influence_m) {
      error(at.at(s.has_safety_margin() ? "safety_margin" : "sphere_of_influence"),
            "schemas: safety_margin " + number(p.safety_margin_m) +
                " must be less than sphere_of_influence " + number(p.sphere_of_influence_m));
    }
    p.noise_persistence_s = positive(s.has_noise_persistence(), s.noise_persistence(),
                                     d.noise_persistence_s, "schemas: noise_persistence",
                                     at.at("noise_persistence"));
    p.teammate_spacing_m = positive(s.has_teammate_spacing(), s.teammate_spacing(),
                                    d.teammate_spacing_m, "schemas: teammate_spacing",
                                    at.at("teammate_spacing"));
    p.comfort_radius_m = non_negative(s.has_comfort_radius(), s.comfort_radius(), d.comfort_radius_m,
                                      "schemas: comfort_radius", at.at("comfort_radius"));
    p.max_radius_m = positive(s.has_max_radius(), s.max_radius(), d.max_radius_m,
                              "schemas: max_radius", at.at("max_radius"));
    if (finite({p.comfort_radius_m, p.max_radius_m}) && p.comfort_radius_m >= p.max_radius_m) {
      error(at.at(s.has_max_radius() ? "max_radius" : "comfort_radius"),
            "schemas: comfort_radius " + number(p.comfort_radius_m) +
                " must be less than max_radius " + number(p.max_radius_m));
    }
    return p;
  }

  std::optional<geometry::Rect> rect(const config::MissionRect& r, const std::string& what, Position at) {
    const geometry::Rect out{r.min_x(), r.min_y(), r.max_x(), r.max_y()};
    if (!finite({out.min_x, out.min_y, out.max_x, out.max_y})) {
      error(at, what + " has a coordinate that is not finite");
      return std::nullopt;
    }
    if (!out.valid()) {
      error(at, what + " is empty or inverted: min (" + number(out.min_x) + ", " + number(out.min_y) +
                    ") must be below max (" + number(out.max_x) + ", " + number(out.max_y) + ")");
      return std::nullopt;
    }
    return out;
  }

  void layers(const config::Mission& file, const Locator& root, MissionSpec& out) {
    std::map<std::string, int> seen;
    for (int i = 0; i < file.layers_size(); ++i) {
      const config::ConstraintLayer& l = file.layers(i);
      const Locator at = root.nested("layers", i);
      if (l.name() == kObstaclesLayer) {
        error(at.at("name"), "layer name obstacles is reserved for the map's obstacles");
        continue;
      }
      if (l.name().find('+') != std::string::npos) {  // a goal's constraint set could never name it
        error(at.at("name"), "layer name " + l.name() + " contains '+', which joins layer names in constraint sets");
        continue;
      }
      if (!unique(seen, l.name(), "layer", l.name().empty() ? at.self() : at.at("name"))) continue;
      ConstraintLayerSpec spec{l.name(), {}};
      if (l.areas_size() == 0) error(at.self(), "layer " + l.name() + " has no areas");
      for (int k = 0; k < l.areas_size(); ++k) {
        if (auto r = rect(l.areas(k), "layer " + l.name() + ": area " + std::to_string(k),
                          at.at("areas", k))) {
          spec.areas.push_back(*r);
        }
      }
      out.layers.push_back(std::move(spec));
    }
  }

  void plan_sets(const config::Mission& file, const Locator& root, MissionSpec& out) {
    std::map<std::string, int> seen;
    for (int i = 0; i < file.plan_sets_size(); ++i) {
      const config::PlanSet& p = file.plan_sets(i);
      const Locator at = root.nested("plan_sets", i);
      if (!unique(seen, p.name(), "plan set", p.name().empty() ? at.self() : at.at("name"))) continue;
      const std::string who = "plan set " + p.name();
      PlanSetSpec spec;
      spec.name = p.name();
      if (!p.has_goal()) {
        error(at.self(), who + ": goal is missing");
      } else if (!finite({p.goal().x(), p.goal().y()})) {
        error(at.at("goal"), who + ": goal is not finite");
      }
      spec.goal = {p.goal().x(), p.goal().y()};
      if (p.layers_size() == 0) {
        error(at.self(), who + ": layers are missing (start with \"obstacles\")");
      }
      std::set<std::string> listed;
      for (int k = 0; k < p.layers_size(); ++k) {
        const std::string& name = p.layers(k);
        const Position where = at.at("layers", k);
        if (k == 0 && name != kObstaclesLayer) {
          error(where, who + ": the first layer must be \"obstacles\" (got \"" + name + "\")");
        } else if (k > 0 && name == kObstaclesLayer) {
          error(where, who + ": \"obstacles\" must be the first layer only");
        } else if (k > 0 && std::none_of(out.layers.begin(), out.layers.end(),
                                         [&](const ConstraintLayerSpec& l) { return l.name == name; })) {
          error(where, who + ": unknown layer " + name);
        } else if (!listed.insert(name).second) {
          error(where, who + ": layer " + name + " is listed twice");
        }
        spec.layers.push_back(name);
      }
      switch (p.selection()) {
        case config::PlanSet::SELECTION_UNSPECIFIED:
        case config::PlanSet::STATIC: spec.selection = PlanSelectionMode::Static; break;
        case config::PlanSet::DYNAMIC: spec.selection = PlanSelectionMode::Dynamic; break;
        case config::PlanSet::BLENDED: spec.selection = PlanSelectionMode::Blended; break;
        default:
          error(at.at("selection"),
                who + ": unknown selection value " + std::to_string(static_cast<int>(p.selection())));
      }
      if (spec.selection == PlanSelectionMode::Blended) {
        if (p.blend_gains_size() != p.layers_size()) {
          error(p.blend_gains_size() > 0 ? at.at("blend_gains", 0) : at.at("selection"),
                who + ": BLENDED needs one blend gain per layer (" +
                    std::to_string(p.layers_size()) + "), got " + std::to_string(p.blend_gains_size()));
        }
        for (int k = 0; k < p.blend_gains_size(); ++k) {
          spec.blend_gains.push_back(non_negative(true, p.blend_gains(k), 0.0,
                                                  who + ": blend gain " + std::to_string(k),
                                                  at.at("blend_gains", k)));
        }
      } else if (p.blend_gains_size() > 0) {
        error(at.at("blend_gains", 0), who + ": blend_gains are only used with selection BLENDED");
      }
      out.plan_sets.push_back(std::move(spec));
    }
  }

  // Gains of a go_to (go_to = true) or a wander; `reactive` is folded into its two schemas.
  SchemaGains gains(const config::SchemaGains& g, const Locator& at, const std::string& who, bool go_to) {
    const pb::Reflection* r = g.GetReflection();
    const pb::Descriptor* d = config::SchemaGains::descriptor();
    for (int i = 0; i < d->field_count(); ++i) {
      const pb::FieldDescriptor* f = d->field(i);
      if (!r->HasField(g, f)) continue;
      const double v = r->GetDouble(g, f);
      if (!(std::isfinite(v) && v >= 0.0)) {
        error(at.at(f->name().c_str()), who + ": gain " + f->name() + " must not be negative (got " +
                                            number(v) + ")");
      }
      if (!go_to && (f->name() == "reactive" || f->name() == "move_to_goal" || f->name() == "plan")) {
        error(at.at(f->name().c_str()), who + ": gain " + f->name() + " has no meaning in wander");
      }
    }
    SchemaGains out;
    if (go_to) {
      const double reactive = g.has_reactive() ? g.reactive() : 1.0;
      out.move_to_goal = reactive * (g.has_move_to_goal() ? g.move_to_goal() : 1.0);
      out.avoid_obstacles = reactive * (g.has_avoid_obstacles() ? g.avoid_obstacles() : 1.0);
      out.plan = g.has_plan() ? g.plan() : 0.0;
      out.noise = g.has_noise() ? g.noise() : 0.0;
    } else {
      out.avoid_obstacles = g.has_avoid_obstacles() ? g.avoid_obstacles() : 1.0;
      out.noise = g.has_noise() ? g.noise() : 1.0;
    }
    out.avoid_teammates = g.has_avoid_teammates() ? g.avoid_teammates() : 0.0;
    out.stay_near_teammates = g.has_stay_near_teammates() ? g.stay_near_teammates() : 0.0;
    return out;
  }

  BehaviorSpec behavior(const config::MissionState& s, const Locator& at, const MissionSpec& mission,
                        const std::string& who) {
    BehaviorSpec b;
    switch (s.behavior_case()) {
      case config::MissionState::kGoTo: {
        b.kind = BehaviorSpec::Kind::GoTo;
        const config::GoToBehavior& g = s.go_to();
        const Locator go = at.nested("go_to");
        const bool has_plan = !g.plan_set().empty();
        if (has_plan && g.has_goal()) {
          error(go.at("goal"), who + ": go_to takes either plan_set or goal, not both");
        } else if (!has_plan && !g.has_goal()) {
          error(go.self(), who + ": go_to needs a plan_set or a goal");
        }
        if (has_plan) {
          b.plan_set = g.plan_set();
          if (const PlanSetSpec* p = mission.plan_set(g.plan_set())) {
            b.goal = p->goal;
          } else {
            error(go.at("plan_set"), who + ": unknown plan set " + g.plan_set());
          }
        } else if (g.has_goal()) {
          b.goal = {g.goal().x(), g.goal().y()};
          if (!finite({b.goal.x(), b.goal.y()})) error(go.at("goal"), who + ": goal is not finite");
        }
        b.tolerance_m = positive(g.has_tolerance(), g.tolerance(), 2.0, who + ": tolerance",
                                 go.at("tolerance"));
        b.gains = gains(g.gains(), go.nested("gains"), who, true);
        if (!has_plan && g.gains().has_plan() && g.gains().plan() > 0.0) {
          error(go.nested("gains").at("plan"), who + ": gain plan needs a plan_set to advise");
        }
        break;
      }
      case config::MissionState::kWait: b.kind = BehaviorSpec::Kind::Wait; break;
      case config::MissionState::kWander: {
        b.kind = BehaviorSpec::Kind::Wander;
        const Locator w = at.nested("wander");
        b.gains = gains(s.wander().gains(), w.nested("gains"), who, false);
        break;
      }
      case config::MissionState::kStop: b.kind = BehaviorSpec::Kind::Stop; break;
      case config::MissionState::BEHAVIOR_NOT_SET:
        error(at.self(), who + ": behavior is missing (go_to, wait, wander or stop)");
        break;
    }
    return b;
  }

  void states(const config::Mission& file, const Locator& root, MissionSpec& out) {
    if (file.states_size() == 0) error(root.self(), "mission has no states");
    // Names first, so that transitions may point forwards.
    for (int i = 0; i < file.states_size(); ++i) {
      const Locator at = root.nested("states", i);
      const std::string& name = file.states(i).name();
      unique(state_lines_, name, "state", name.empty() ? at.self() : at.at("name"));
    }
    for (int i = 0; i < file.states_size(); ++i) {
      const config::MissionState& s = file.states(i);
      const Locator at = root.nested("states", i);
      const std::string who = "state " + (s.name().empty() ? "#" + std::to_string(i) : s.name());
      StateSpec spec;
      spec.name = s.name();
      spec.behavior = behavior(s, at, out, who);
      if (spec.behavior.kind == BehaviorSpec::Kind::Stop && s.transitions_size() > 0) {
        error(at.at("transitions", 0), who + ": a stop state ends the mission; remove its transitions");
      }
      for (int k = 0; k < s.transitions_size(); ++k) {
        const config::MissionTransition& t = s.transitions(k);
        const Locator tat = at.nested("transitions", k);
        TransitionSpec ts;
        ts.to = t.to();
        if (t.to().empty()) {
          error(tat.self(), who + ": transition " + std::to_string(k) + " has no target state (to)");
        } else if (state_lines_.count(t.to()) == 0) {
          error(tat.at("to"), who + ": transition to unknown state " + t.to());
        }
        if (!t.has_when()) {
          error(tat.self(), who + ": transition to " + t.to() + " has no trigger (when)");
        } else {
          ts.when = trigger(t.when(), tat.nested("when"), who, spec.behavior.kind, out);
        }
        spec.transitions.push_back(std::move(ts));
      }
      out.states.push_back(std::move(spec));
    }
  }

  std::string contact_teammate(const config::ContactTrigger& c, const Locator& at, const std::string& who,
                               const std::string& trigger_name, const MissionSpec& mission) {
    if (c.teammate().empty()) {
      if (mission.teammates.empty()) {
        error(at.self(), who + ": " + trigger_name +
                             " without a teammate needs the mission's teammates list");
      }
    } else if (std::find(mission.teammates.begin(), mission.teammates.end(), c.teammate()) ==
               mission.teammates.end()) {
      error(at.at("teammate"), who + ": " + trigger_name + " names unknown teammate " + c.teammate());
    }
    return c.teammate();
  }

  TriggerSpec trigger(const config::PerceptualTrigger& t, const Locator& at, const std::string& who,
                      BehaviorSpec::Kind behavior, const MissionSpec& mission) {
    TriggerSpec spec;
    using Kind = TriggerSpec::Kind;
    switch (t.kind_case()) {
      case config::PerceptualTrigger::kAtGoal:
        spec.kind = Kind::AtGoal;
        if (behavior != BehaviorSpec::Kind::GoTo) {
          error(at.at("at_goal"), who + ": at_goal needs a go_to state (this state has no goal)");
        }
        break;
      case config::PerceptualTrigger::kInArea: {
        spec.kind = Kind::InArea;
        const config::TriggerArea& a = t.in_area();
        const Locator aat = at.nested("in_area");
        switch (a.shape_case()) {
          case config::TriggerArea::kCircle: {
            spec.area.shape = Area::Shape::Circle;
            const config::MissionCircle& c = a.circle();
            const Locator cat = aat.nested("circle");
            if (!c.has_center()) error(cat.self(), who + ": in_area circle has no center");
            spec.area.circle = {{c.center().x(), c.center().y()}, c.radius()};
            if (!(std::isfinite(c.radius()) && c.radius() > 0.0)) {
              error(cat.at("radius"),
                    who + ": in_area circle radius must be positive (got " + number(c.radius()) + ")");
            }
            break;
          }
          case config::TriggerArea::kRect:
            spec.area.shape = Area::Shape::Rect;
            if (auto r = rect(a.rect(), who + ": in_area rect", aat.at("rect"))) spec.area.rect = *r;
            break;
          case config::TriggerArea::SHAPE_NOT_SET:
            error(aat.self(), who + ": in_area needs a circle or a rect");
            break;
        }
        break;
      }
      case config::PerceptualTrigger::kLostContact:
        spec.kind = Kind::LostContact;
        spec.teammate = contact_teammate(t.lost_contact(), at.nested("lost_contact"), who,
                                         "lost_contact", mission);
        break;
      case config::PerceptualTrigger::kContactRestored:
        spec.kind = Kind::ContactRestored;
        spec.teammate = contact_teammate(t.contact_restored(), at.nested("contact_restored"), who,
                                         "contact_restored", mission);
        break;
      case config::PerceptualTrigger::kTimeout: {
        spec.kind = Kind::Timeout;
        spec.seconds = t.timeout().seconds();
        const Locator tat = at.nested("timeout");
        if (!(std::isfinite(spec.seconds) && spec.seconds > 0.0)) {
          error(tat.at("seconds"),
                who + ": timeout seconds must be positive (got " + number(spec.seconds) + ")");
        }
        break;
      }
      case config::PerceptualTrigger::kAllOf:
      case config::PerceptualTrigger::kAnyOf: {
        const bool all = t.kind_case() == config::PerceptualTrigger::kAllOf;
        spec.kind = all ? Kind::AllOf : Kind::AnyOf;
        const char* field = all ? "all_of" : "any_of";
        const config::TriggerList& list = all ? t.all_of() : t.any_of();
        const Locator lat = at.nested(field);
        if (list.triggers_size() == 0) error(lat.self(), who + ": " + field + " has no triggers");
        for (int i = 0; i < list.triggers_size(); ++i) {
          spec.children.push_back(trigger(list.triggers(i), lat.nested("triggers", i), who, behavior, mission));
        }
        break;
      }
      case config::PerceptualTrigger::KIND_NOT_SET:
        error(at.self(), who + ": trigger is empty (at_goal, in_area, lost_contact, "
                               "contact_restored, timeout, all_of or any_of)");
        break;
    }
    return spec;
  }

  const std::string& source_;
  std::vector<MissionError>& errors_;
  std::map<std::string, int> state_lines_;  // name -> line of its definition
};

}  // namespace

std::string MissionLoadResult::error_text() const { return configfile::error_text(errors); }

MissionLoadResult load_mission_text(const std::string& text, const std::string& source_name) {
  MissionLoadResult result;
  ParseInfoTree tree;
  config::Mission file;
  if (!configfile::parse_text_format(text, source_name, file, tree, result.errors)) return result;
  MissionSpec mission = MissionChecker(source_name, result.errors).check(file, tree);
  configfile::sort_by_position(result.errors);
  if (result.errors.empty()) result.mission = std::move(mission);
  return result;
}

MissionLoadResult load_mission_file(const std::string& path) {
  MissionLoadResult result;
  const std::optional<std::string> text = configfile::read_text_file(path, result.errors);
  return text ? load_mission_text(*text, path) : result;
}

}  // namespace autonomy::behavior
