#include "services/behavior/core/mission/mission_executor.hpp"

#include "services/behavior/core/schemas/avoid_obstacles.hpp"
#include "services/behavior/core/schemas/move_to_goal.hpp"
#include "services/behavior/core/schemas/noise.hpp"
#include "services/behavior/core/schemas/teammate_schemas.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

namespace autonomy::behavior {

struct MissionExecutor::CompiledState {
  std::vector<std::unique_ptr<PerceptualTrigger>> triggers;  // parallel to spec.transitions
  std::vector<std::size_t> targets;                          // state index of each transition
  std::shared_ptr<const PlanSet> plans;                      // GoTo with a plan set
};

struct MissionExecutor::Active {
  std::size_t index = 0;
  double entered_at_s = 0.0;
  SchemaBlend blend;
  const PlanAdvice* plan = nullptr;  // owned by blend
  bool static_pending = false;
  std::string chosen_plan;  // static selection's choice, by name

};

std::string MissionEvent::to_string() const {
  std::ostringstream s;
  s << "t=" << time_s << " ";
  switch (kind) {
    case Kind::Started: s << "started in " << state; break;
    case Kind::Transition: s << from << " -> " << state << ": " << reason; break;
    case Kind::PlanChosen: s << state << ": static selection chose plan " << reason; break;
    case Kind::NoViablePlan: s << state << ": no plan has a route from here yet"; break;
    case Kind::Finished: s << "finished in " << state; break;
    case Kind::Resumed: s << "resumed in " << state << ": " << reason; break;
  }
  return s.str();
}

namespace {

std::size_t index_of(const MissionSpec& spec, const std::string& name, const std::string& what) {
  for (std::size_t i = 0; i < spec.states.size(); ++i) {
    if (spec.states[i].name == name) return i;
  }
  throw std::invalid_argument(what + ": unknown state " + name);
}

}  // namespace

MissionExecutor::MissionExecutor(MissionSpec spec, PlanLibrary plans, MissionExecutorOptions options)
    : spec_(std::move(spec)), plans_(std::move(plans)), options_(options) {
  if (spec_.states.empty()) throw std::invalid_argument("mission has no states");
  initial_ = index_of(spec_, spec_.initial_state, "initial_state");
  // Construct each schema once with the mission's parameters so bad values throw here, not later.
  (void)MoveToGoal({spec_.schemas.slowdown_radius_m});
  (void)AvoidObstacles({spec_.schemas.sphere_of_influence_m, spec_.schemas.safety_margin_m});
  (void)Noise({spec_.schemas.noise_persistence_s, 0});
  (void)StayNearTeammates({spec_.schemas.comfort_radius_m, spec_.schemas.max_radius_m});
  for (const StateSpec& s : spec_.states) {
    CompiledState c;
    for (const TransitionSpec& t : s.transitions) {
      c.triggers.push_back(make_trigger(t.when));
      c.targets.push_back(index_of(spec_, t.to, "state " + s.name));
    }
    if (s.behavior.kind == BehaviorSpec::Kind::GoTo && !s.behavior.plan_set.empty()) {
      const auto it = plans_.find(s.behavior.plan_set);
      if (it == plans_.end() || !it->second) {
        throw std::invalid_argument("state " + s.name + ": plan set " + s.behavior.plan_set +
                                    " was not built");
      }
      c.plans = it->second;
    }
    states_.push_back(std::move(c));
  }
}

MissionExecutor::~MissionExecutor() = default;
MissionExecutor::MissionExecutor(MissionExecutor&&) noexcept = default;
MissionExecutor& MissionExecutor::operator=(MissionExecutor&&) noexcept = default;

const std::string& MissionExecutor::state() const {
  return spec_.states[active_ ? active_->index : initial_].name;
}

bool MissionExecutor::finished() const {
  return active_ && spec_.states[active_->index].behavior.kind == BehaviorSpec::Kind::Stop;
}

std::optional<geometry::Vec2> MissionExecutor::goal() const {
  const BehaviorSpec& b = spec_.states[active_ ? active_->index : initial_].behavior;
  if (b.kind != BehaviorSpec::Kind::GoTo) return std::nullopt;
  return b.goal;
}

void MissionExecutor::enter(std::size_t index, const Perception& p, std::vector<MissionEvent>& events,
                            const std::string& preferred_plan) {
  const StateSpec& s = spec_.states[index];
  const SchemaParameters& k = spec_.schemas;
  const SchemaGains& g = s.behavior.gains;
  auto next = std::make_unique<Active>();
  next->index = index;
  next->entered_at_s = p.time_s;

  const bool go_to = s.behavior.kind == BehaviorSpec::Kind::GoTo;
  const bool wander = s.behavior.kind == BehaviorSpec::Kind::Wander;
  if (go_to || wander) {
    SchemaBlend& blend = next->blend;
    if (go_to) blend.add(std::make_unique<MoveToGoal>(MoveToGoalConfig{k.slowdown_radius_m}), g.move_to_goal);
    blend.add(std::make_unique<AvoidObstacles>(
                  AvoidObstaclesConfig{k.sphere_of_influence_m, k.safety_margin_m}),
              g.avoid_obstacles);
    blend.add(std::make_unique<Noise>(NoiseConfig{k.noise_persistence_s, options_.noise_seed}), g.noise);
    if (g.avoid_teammates > 0.0) {
      blend.add(std::make_unique<AvoidTeammates>(
                    AvoidObstaclesConfig{k.teammate_spacing_m, 0.0}),
                g.avoid_teammates);
    }
    if (g.stay_near_teammates > 0.0) {
      blend.add(std::make_unique<StayNearTeammates>(StayNearConfig{k.comfort_radius_m, k.max_radius_m}),
                g.stay_near_teammates);
    }
  }
  active_ = std::move(next);

  const CompiledState& c = states_[index];
  if (go_to && c.plans && g.plan > 0.0) {
    const PlanSetSpec* ps = spec_.plan_set(s.behavior.plan_set);
    const PlanSelectionMode mode = ps != nullptr ? ps->selection : PlanSelectionMode::Static;
    if (mode == PlanSelectionMode::Static) {
      active_->static_pending = true;
      try_static_choice(p, events, preferred_plan);
      if (active_->static_pending) {
        events.push_back({MissionEvent::Kind::NoViablePlan, p.time_s, s.name, "", ""});
      }
    } else {
      std::shared_ptr<const PlanSelector> selector;
      if (mode == PlanSelectionMode::Dynamic) {
        selector = std::make_shared<const DynamicPlanSelector>();
      } else {
        selector = std::make_shared<const BlendedPlanSelector>(ps->blend_gains);
      }
      auto schema = std::make_unique<PlanAdvice>(c.plans, std::move(selector));
      active_->plan = schema.get();
      active_->blend.add(std::move(schema), g.plan);
    }
  }
  if (s.behavior.kind == BehaviorSpec::Kind::Stop) {
    events.push_back({MissionEvent::Kind::Finished, p.time_s, s.name, "", ""});
  }
}

void MissionExecutor::try_static_choice(const Perception& p, std::vector<MissionEvent>& events,
                                        const std::string& preferred_plan) {
  Active& a = *active_;
  const CompiledState& c = states_[a.index];
  std::unique_ptr<FixedPlanSelector> chosen;
  for (std::size_t i = 0; i < c.plans->plans().size() && !preferred_plan.empty(); ++i)
    if (c.plans->plans()[i].name() == preferred_plan) chosen = std::make_unique<FixedPlanSelector>(i);
  if (!chosen) chosen = choose_static_plan(*c.plans, p.pose.position());
  if (!chosen) return;
  const std::string& plan_name = c.plans->plans()[chosen->index()].name();
  a.chosen_plan = plan_name;
  auto schema = std::make_unique<PlanAdvice>(c.plans, std::shared_ptr<const PlanSelector>(std::move(chosen)));
  a.plan = schema.get();
  a.blend.add(std::move(schema), spec_.states[a.index].behavior.gains.plan);
  a.static_pending = false;
  events.push_back({MissionEvent::Kind::PlanChosen, p.time_s, spec_.states[a.index].name, "",
                    plan_name});
}

std::vector<MissionEvent> MissionExecutor::resume(const MissionProgress& progress, const Perception& p,
                                                  const std::string& reason) {
  if (active_) throw std::logic_error("resume: the mission has started already");
  const std::size_t index = index_of(spec_, progress.state, "resumed mission");
  std::vector<MissionEvent> entered;
  enter(index, p, entered, progress.plan);
  active_->entered_at_s = progress.entered_at_s;
  std::vector<MissionEvent> events{{MissionEvent::Kind::Resumed, p.time_s, progress.state, "", reason}};
  for (MissionEvent& e : entered) {
    // What the earlier executor announced already is not announced twice.
    const bool known = e.kind == MissionEvent::Kind::Finished ||
                       (e.kind == MissionEvent::Kind::PlanChosen && e.reason == progress.plan);
    if (!known) events.push_back(std::move(e));
  }
  return events;
}

std::optional<MissionProgress> MissionExecutor::progress() const {
  if (!active_) return std::nullopt;
  return MissionProgress{spec_.states[active_->index].name, active_->entered_at_s, active_->chosen_plan};
}

MissionStep MissionExecutor::step(const Perception& p) {
  MissionStep out;
  if (!active_) {
    enter(initial_, p, out.events);
    out.events.insert(out.events.begin(),
                      {MissionEvent::Kind::Started, p.time_s, spec_.states[initial_].name, "", ""});
  }

  for (std::size_t hops = 0; hops < spec_.states.size() && !finished(); ++hops) {
    const StateSpec& s = spec_.states[active_->index];
    const CompiledState& c = states_[active_->index];
    const bool go_to = s.behavior.kind == BehaviorSpec::Kind::GoTo;
    const TriggerContext context{p, p.time_s - active_->entered_at_s,
                                 go_to ? std::optional<geometry::Vec2>(s.behavior.goal) : std::nullopt,
                                 s.behavior.tolerance_m, spec_.teammates};
    std::optional<std::size_t> target;
    std::string reason;
    for (std::size_t i = 0; i < c.triggers.size() && !target; ++i) {
      if (auto why = c.triggers[i]->fires(context)) {
        target = c.targets[i];
        reason = std::move(*why);
      }
    }
    if (!target) break;
    const std::string from = s.name;
    out.events.push_back({MissionEvent::Kind::Transition, p.time_s, spec_.states[*target].name,
                          from, std::move(reason)});
    enter(*target, p, out.events);
  }

  if (active_->static_pending) try_static_choice(p, out.events);

  const StateSpec& s = spec_.states[active_->index];
  out.state = s.name;
  out.behavior = s.behavior.kind;
  out.finished = finished();
  if (active_->blend.empty()) return out;

  Perception view = p;
  view.goal = s.behavior.kind == BehaviorSpec::Kind::GoTo
                  ? std::optional<geometry::Vec2>(s.behavior.goal)
                  : std::nullopt;
  out.blend = active_->blend.blend(view);
  out.velocity = out.blend.velocity;
  out.command = to_velocity_command(out.velocity, p.pose, p.kinematics, p.limits, options_.steering);
  if (active_->plan != nullptr) out.plan = active_->plan->selection(p.pose.position());
  return out;
}

}  // namespace autonomy::behavior
