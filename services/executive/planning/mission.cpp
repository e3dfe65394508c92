#include "mission.hpp"

#include <algorithm>

#include "planner_language.hpp"

namespace autonomy::executive {
namespace {

// Moves a window of mission time to plan time `origin`; false when it closed before origin.
bool shift(pb::Bounds* b, MissionTime origin) {
  if (b->ub() < origin) return false;
  b->set_lb(std::max<MissionTime>(0, b->lb() - origin));
  b->set_ub(b->ub() - origin);
  return true;
}

}  // namespace

std::optional<Mission> Mission::load(const std::string& model_path, const std::string& problem_path,
                                     std::string* error) {
  planner::Diagnostics errors;
  auto model = planner::read_text_file(model_path, &errors);
  auto problem = model ? planner::read_text_file(problem_path, &errors) : std::nullopt;
  if (!model || !problem) {
    *error = planner::to_string(errors);
    return std::nullopt;
  }
  return parse(std::move(*model), model_path, *problem, problem_path, error);
}

std::optional<Mission> Mission::parse(std::string model_text, const std::string& model_file,
                                      const std::string& problem_text, const std::string& problem_file,
                                      std::string* error) {
  planner::Diagnostics errors;
  // The model is sent as text (the planner reports its errors against the file); it is parsed
  // here only to fail early, with positions, before anything flies.
  if (!planner::parse_model(model_text, model_file, &errors)) {
    *error = planner::to_string(errors);
    return std::nullopt;
  }
  auto problem = planner::parse_problem(problem_text, problem_file, &errors);
  if (!problem) {
    *error = planner::to_string(errors);
    return std::nullopt;
  }
  if (problem->horizon() <= 0) {
    *error = problem_file + ": the mission needs a horizon";
    return std::nullopt;
  }
  return Mission(std::move(model_text), model_file, std::move(*problem), problem_file);
}

std::set<std::string> Mission::state_timelines() const {
  std::set<std::string> out;
  for (const pb::Fact& f : problem_.initial()) out.insert(f.object() + "." + f.attribute());
  return out;
}

std::optional<msg::PlannerTimelineValue> Mission::initial_value(const std::string& timeline) const {
  for (const pb::Fact& f : problem_.initial()) {
    if (f.object() + "." + f.attribute() != timeline) continue;
    msg::PlannerTimelineValue v{timeline, f.predicate(), {}};
    for (const pb::Argument& a : f.arguments()) {
      if (a.has_number()) {
        const double x = a.number();
        v.parameters.push_back(x == static_cast<double>(static_cast<long long>(x))
                                   ? std::to_string(static_cast<long long>(x))
                                   : std::to_string(x));
      } else {
        v.parameters.push_back(a.symbol());
      }
    }
    return v;
  }
  return std::nullopt;
}

std::vector<std::string> Mission::goal_labels() const {
  std::vector<std::string> labels;
  for (const pb::Fact& g : problem_.goals()) labels.push_back(g.label());
  return labels;
}

std::string Mission::goal_timeline(const std::string& label) const {
  for (const pb::Fact& g : problem_.goals())
    if (g.label() == label) return g.object() + "." + g.attribute();
  return "";
}

GoalWindowCut Mission::request(MissionTime origin, MissionTime end,
                               const std::vector<msg::PlannerTimelineValue>& state,
                               const std::set<std::string>& settled,
                               const std::map<std::string, std::string>& impossible,
                               const std::set<std::string>& executing,
                               bool every_goal_optional) const {
  GoalWindowCut cut;
  end = std::min(end, problem_.horizon());
  pb::Problem p = problem_;
  p.set_horizon(std::max<MissionTime>(1, end - origin));
  p.clear_goals();
  p.clear_relations();
  std::set<std::string> kept;
  for (const pb::Fact& goal : problem_.goals()) {
    if (settled.count(goal.label())) continue;
    auto blocked = impossible.find(goal.object() + "." + goal.attribute());
    if (blocked != impossible.end()) {
      cut.lost[goal.label()] = blocked->second;
      continue;
    }
    pb::Fact g = goal;
    if (g.has_start() && g.start().lb() >= end) continue;  // a later horizon's
    if (executing.count(g.label())) {
      g.mutable_start()->set_lb(origin);
      g.mutable_start()->set_ub(origin);
    }
    if ((g.has_start() && !shift(g.mutable_start(), origin)) ||
        (g.has_end() && !shift(g.mutable_end(), origin))) {
      cut.lost[goal.label()] = "its window closed before " + std::to_string(origin) + " s";
      continue;
    }
    if (every_goal_optional && !g.optional()) {
      g.set_optional(true);
      g.set_penalty(1);
    }
    kept.insert(g.label());
    cut.goals.push_back(g.label());
    *p.add_goals() = std::move(g);
  }
  for (const pb::FactRelation& r : problem_.relations())
    if (kept.count(r.from()) && kept.count(r.to())) *p.add_relations() = r;

  msg::PlanningRequest& q = cut.request;
  q.model_file = model_file_;
  q.model_text = model_text_;
  q.problem_file = problem_file_;
  const std::string bytes = p.SerializeAsString();
  q.problem_protobuf.assign(bytes.begin(), bytes.end());
  q.state = state;
  q.plan_origin = origin;
  return cut;
}

}  // namespace autonomy::executive
