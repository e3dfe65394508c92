// The only file that compiles OMPL's headers (see ompl_path_planner.hpp).
#include "services/behavior/core/path/ompl_path_planner.hpp"

#include "services/behavior/core/cost_to_go_field.hpp"
#include "services/behavior/core/path/grid_path_planner.hpp"

#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/DubinsStateSpace.h>
#include <ompl/base/spaces/ReedsSheppStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/tools/benchmark/Benchmark.h>
#include <ompl/tools/benchmark/MachineSpecs.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace autonomy::behavior {

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

// Octile over Euclidean length is at most this (22.5 degree lines), so the grid optimum divided by
// it, less a couple of cells for the endpoints, is a lower bound of the continuous path's length.
constexpr double kOctileOverEuclid = 1.0824;

ob::PlannerPtr make_planner(const std::string& name, const ob::SpaceInformationPtr& si) {
  if (name == "RRTConnect") return std::make_shared<og::RRTConnect>(si);
  if (name == "RRT") return std::make_shared<og::RRT>(si);
  if (name == "RRTstar") return std::make_shared<og::RRTstar>(si);
  if (name == "InformedRRTstar") return std::make_shared<og::InformedRRTstar>(si);
  if (name == "PRMstar") return std::make_shared<og::PRMstar>(si);
  if (name == "BITstar") return std::make_shared<og::BITstar>(si);
  if (name == "KPIECE1") return std::make_shared<og::KPIECE1>(si);
  return nullptr;
}

PathResult failure(PathStatus status, std::string reason) {
  PathResult r;
  r.status = status;
  r.reason = std::move(reason);
  return r;
}

// OMPL 1.5.2's Dubins curves assert their own arithmetic (dubinsRSR, dubinsRSL, ...; Debian keeps
// the asserts) and abort the process when rounding breaks an asserted identity. Measured with
// 2,000,000 near-coincident pairs (path_planner_test.cpp, DubinsCurves, has the class): 1,002 aborted,
// every one with headings within 1e-6 rad of each other and the second position under 1.8e-3
// turning radii ahead of or behind the first along that heading; none elsewhere. Planners and the
// path simplifier make such pairs themselves (interpolating, shortcutting), so the inputs cannot
// be guarded before OMPL sees them: this space guards every distance and interpolation. A pair that
// close is one pose for the robot; a straight motion stands in for the curve (margins: 100 times
// the measured angle, 5 times the distance).
constexpr double kDubinsSameHeadingRad = 1e-4;
constexpr double kDubinsSamePlaceRadii = 1e-2;

class GuardedDubinsStateSpace final : public ob::DubinsStateSpace {
 public:
  explicit GuardedDubinsStateSpace(double turning_radius)
      : DubinsStateSpace(turning_radius, false), radius_(turning_radius) {}
  using DubinsStateSpace::interpolate;

  double distance(const ob::State* a, const ob::State* b) const override {
    if (nearly_same(a, b)) return straight_length(a, b);
    return DubinsStateSpace::distance(a, b);
  }
  void interpolate(const ob::State* from, const ob::State* to, double t, ob::State* state) const override {
    if (nearly_same(from, to))
      straight(from, to, t, state);
    else
      DubinsStateSpace::interpolate(from, to, t, state);
  }
  void interpolate(const ob::State* from, const ob::State* to, double t, bool& first_time, DubinsPath& path,
                   ob::State* state) const override {
    if (nearly_same(from, to))
      straight(from, to, t, state);
    else
      DubinsStateSpace::interpolate(from, to, t, first_time, path, state);
  }

 private:
  static const StateType& se2(const ob::State* s) { return *s->as<StateType>(); }
  static double turn(const ob::State* a, const ob::State* b) {
    return std::remainder(se2(b).getYaw() - se2(a).getYaw(), 2.0 * M_PI);
  }
  static double straight_length(const ob::State* a, const ob::State* b) {
    return std::hypot(se2(b).getX() - se2(a).getX(), se2(b).getY() - se2(a).getY());
  }
  bool nearly_same(const ob::State* a, const ob::State* b) const {
    return std::fabs(turn(a, b)) < kDubinsSameHeadingRad && straight_length(a, b) < kDubinsSamePlaceRadii * radius_;
  }
  void straight(const ob::State* from, const ob::State* to, double t, ob::State* state) const {
    auto* out = state->as<StateType>();
    out->setXY(se2(from).getX() + t * (se2(to).getX() - se2(from).getX()),
               se2(from).getY() + t * (se2(to).getY() - se2(from).getY()));
    out->setYaw(std::remainder(se2(from).getYaw() + t * turn(from, to), 2.0 * M_PI));
  }

  double radius_;
};

// The heading the grid route arrives with: from the route's pose about 0.5 m before the goal.
double arrival_heading(const std::vector<geometry::Pose2>& route, double fallback) {
  if (route.size() < 2) return fallback;
  const geometry::Vec2 goal = route.back().position();
  for (std::size_t i = route.size() - 1; i-- > 0;) {
    const geometry::Vec2 d = goal - route[i].position();
    if (d.norm() >= 0.5 || i == 0) {
      return d.norm() > 1e-9 ? std::atan2(d.y(), d.x()) : fallback;
    }
  }
  return fallback;
}

// Half the samples near the grid route (Gaussian around a random pose of it, heading along it or,
// for reversing robots, against it), half uniform: narrow doorways are a thin slice of SE(2) that
// uniform sampling rarely hits, and the route says where they are.
class RouteBiasedSampler : public ob::StateSampler {
 public:
  RouteBiasedSampler(const ob::StateSpace* space,
                     std::shared_ptr<const std::vector<geometry::Pose2>> route, bool reverse_too)
      : StateSampler(space),
        uniform_(space->allocDefaultStateSampler()),
        route_(std::move(route)),
        reverse_too_(reverse_too) {}

  void sampleUniform(ob::State* state) override {
    if (route_->empty() || rng_.uniform01() < 0.5) {
      uniform_->sampleUniform(state);
      return;
    }
    const auto& p = (*route_)[static_cast<std::size_t>(
        rng_.uniformInt(0, static_cast<int>(route_->size()) - 1))];
    auto* se2 = state->as<ob::SE2StateSpace::StateType>();
    const double flip = reverse_too_ && rng_.uniform01() < 0.5 ? M_PI : 0.0;
    se2->setXY(rng_.gaussian(p.x, 0.15), rng_.gaussian(p.y, 0.15));
    se2->setYaw(rng_.gaussian(p.theta + flip, 0.3));
    space_->enforceBounds(state);
  }
  void sampleUniformNear(ob::State* state, const ob::State* near, double distance) override {
    uniform_->sampleUniformNear(state, near, distance);
  }
  void sampleGaussian(ob::State* state, const ob::State* mean, double std_dev) override {
    uniform_->sampleGaussian(state, mean, std_dev);
  }

 private:
  ob::StateSamplerPtr uniform_;
  std::shared_ptr<const std::vector<geometry::Pose2>> route_;
  bool reverse_too_;
};

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The route's direction at pose i, over about +-0.3 m: the 8-connected route turns in 45 degree
// steps, a heading averaged over a few cells is what a curve through it should have.
double route_heading(const std::vector<geometry::Pose2>& route, std::size_t i, std::size_t half) {
  const std::size_t a = i >= half ? i - half : 0;
  const std::size_t b = std::min(route.size() - 1, i + half);
  const geometry::Vec2 d = route[b].position() - route[a].position();
  return d.norm() > 1e-9 ? std::atan2(d.y(), d.x()) : route[i].theta;
}

// The grid route as a guide (OmplPlannerSettings::route_guide): greedy hops from the start to
// the farthest route pose within `reach_m` that one valid motion reaches, then on from there; the
// last hop ends in `goal`. Empty when a hop finds no reachable pose or time runs out.
std::optional<og::PathGeometric> route_guided_path(const ob::SpaceInformationPtr& si,
                                                   const std::vector<geometry::Pose2>& route,
                                                   const ob::State* start, const ob::State* goal,
                                                   double resolution_m, double reach_m,
                                                   const ob::PlannerTerminationCondition& stop) {
  if (route.size() < 2) return std::nullopt;
  const auto space = si->getStateSpace();
  const std::size_t half = std::max<std::size_t>(1, static_cast<std::size_t>(0.3 / resolution_m));
  // Candidates every ~0.2 m of the route (route poses are cell to cell), the goal last.
  const std::size_t stride = std::max<std::size_t>(1, static_cast<std::size_t>(0.2 / resolution_m));
  std::vector<std::size_t> index;
  std::vector<double> along;  // metres along the route to each candidate
  double s = 0.0;
  for (std::size_t i = 1; i + 1 < route.size(); ++i) {
    s += (route[i].position() - route[i - 1].position()).norm();
    if (i % stride == 0) {
      index.push_back(i);
      along.push_back(s);
    }
  }
  s += (route.back().position() - route[route.size() - 2].position()).norm();
  index.push_back(route.size() - 1);
  along.push_back(s);

  std::vector<ob::State*> states;
  for (std::size_t k = 0; k + 1 < index.size(); ++k) {
    ob::State* st = si->allocState();
    auto* se2 = st->as<ob::SE2StateSpace::StateType>();
    se2->setXY(route[index[k]].x, route[index[k]].y);
    se2->setYaw(route_heading(route, index[k], half));
    space->enforceBounds(st);
    states.push_back(st);
  }
  const auto candidate = [&](std::size_t k) -> const ob::State* {
    return k + 1 == index.size() ? goal : states[k];
  };
  // The farthest candidate one motion from `from` reaches, scanning back from `reach_m` ahead.
  const auto farthest = [&](const ob::State* from, std::size_t next,
                            double from_along) -> std::optional<std::size_t> {
    std::size_t last = next;
    while (last + 1 < index.size() && along[last + 1] - from_along <= reach_m) ++last;
    for (std::size_t k = last + 1; k-- > next;) {
      if (si->isValid(candidate(k)) && si->checkMotion(from, candidate(k))) return k;
    }
    return std::nullopt;
  };
  // Stuck (typically at the start: facing a wall, too close to turn on the curve): a short
  // manoeuvre first, straight forward or back by up to half a metre, turning by up to 90 degrees.
  ob::State* via = si->allocState();
  const auto manoeuvre = [&](const ob::State* from, std::size_t next,
                             double from_along) -> std::optional<std::size_t> {
    const auto* f = from->as<ob::SE2StateSpace::StateType>();
    for (const double d : {-0.3, 0.3, -0.5, 0.5, 0.0}) {
      for (const double turn : {0.0, M_PI / 4, -M_PI / 4, M_PI / 2, -M_PI / 2}) {
        if (d == 0.0 && turn == 0.0) continue;
        auto* v = via->as<ob::SE2StateSpace::StateType>();
        v->setXY(f->getX() + d * std::cos(f->getYaw()), f->getY() + d * std::sin(f->getYaw()));
        v->setYaw(f->getYaw() + turn);
        space->enforceBounds(via);
        if (!si->isValid(via) || !si->checkMotion(from, via)) continue;
        if (auto k = farthest(via, next, from_along)) return k;
      }
    }
    return std::nullopt;
  };
  std::optional<og::PathGeometric> path(std::in_place, si, start);
  const ob::State* from = start;
  double from_along = 0.0;
  std::size_t next = 0;  // first candidate not behind `from`
  while (from != goal) {
    if (stop()) {
      path.reset();
      break;
    }
    std::optional<std::size_t> reached = farthest(from, next, from_along);
    if (!reached) {
      reached = manoeuvre(from, next, from_along);
      if (reached) path->append(via);
    }
    if (!reached) {
      path.reset();
      break;
    }
    from = candidate(*reached);
    from_along = along[*reached];
    next = *reached + 1;
    path->append(from);
  }
  si->freeState(via);
  for (ob::State* st : states) si->freeState(st);
  return path;
}

}  // namespace

const char* to_string(CurveModel m) {
  switch (m) {
    case CurveModel::Dubins:
      return "dubins";
    case CurveModel::ReedsShepp:
      return "reeds_shepp";
    case CurveModel::Holonomic:
      return "se2";
  }
  return "unknown";
}

std::optional<CurveModel> parse_curve_model(const std::string& text) {
  for (CurveModel m : {CurveModel::Dubins, CurveModel::ReedsShepp, CurveModel::Holonomic}) {
    if (text == to_string(m)) return m;
  }
  return std::nullopt;
}

// LazyPRMstar is not offered: in OMPL 1.5.2 (Debian 12) its solve() leaks the states it clones
// (LeakSanitizer, in libompl's own frames), so every query would leak.
const std::vector<std::string>& ompl_planner_names() {
  static const std::vector<std::string> names{"RRTConnect", "RRT",     "RRTstar", "InformedRRTstar",
                                              "PRMstar",    "BITstar", "KPIECE1"};
  return names;
}

std::optional<std::string> settings_problem(const OmplPlannerSettings& s) {
  const auto& names = ompl_planner_names();
  if (std::find(names.begin(), names.end(), s.planner) == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    return "unknown planner '" + s.planner + "' (known: " + known + ")";
  }
  if (s.curve != CurveModel::Holonomic &&
      !(s.turning_radius_m > 0.0 && std::isfinite(s.turning_radius_m))) {
    return "turning radius must be positive and finite";
  }
  if (!(s.motion_step_m > 0.0 && s.motion_step_m <= 0.05))
    return "motion step must be in (0, 0.05] m";
  if (!(s.route_guide_reach_m > 0.0 && std::isfinite(s.route_guide_reach_m)))
    return "route guide reach must be positive and finite";
  if (!(s.good_enough_ratio >= 1.0 && std::isfinite(s.good_enough_ratio))) {
    return "good-enough ratio must be finite and at least 1";
  }
  return std::nullopt;
}

void seed_ompl(std::uint32_t seed) {
  ompl::RNG::setSeed(seed);
}

struct OmplPathPlanner::Impl {
  std::shared_ptr<const OccupancyGrid> grid;
  ob::StateSpacePtr space;
};

OmplPathPlanner::OmplPathPlanner(std::shared_ptr<const OccupancyGrid> grid,
                                 OmplPlannerSettings settings)
    : settings_(std::move(settings)), impl_(std::make_unique<Impl>()) {
  if (!grid) throw std::invalid_argument("OMPL path planner needs a grid");
  if (auto problem = settings_problem(settings_)) throw std::invalid_argument(*problem);
  ompl::msg::setLogLevel(ompl::msg::LOG_NONE);  // failures come back as statuses with reasons
  impl_->grid = std::move(grid);
  switch (settings_.curve) {
    case CurveModel::Dubins:
      impl_->space = std::make_shared<GuardedDubinsStateSpace>(settings_.turning_radius_m);
      break;
    case CurveModel::ReedsShepp:
      impl_->space = std::make_shared<ob::ReedsSheppStateSpace>(settings_.turning_radius_m);
      break;
    case CurveModel::Holonomic:
      impl_->space = std::make_shared<ob::SE2StateSpace>();
      break;
  }
  ob::RealVectorBounds bounds(2);
  bounds.setLow(0, 0.0);
  bounds.setLow(1, 0.0);
  bounds.setHigh(0, impl_->grid->width_m());
  bounds.setHigh(1, impl_->grid->height_m());
  impl_->space->as<ob::SE2StateSpace>()->setBounds(bounds);
}

OmplPathPlanner::~OmplPathPlanner() = default;

PathResult OmplPathPlanner::plan(const PathRequest& request) {
  const auto t0 = std::chrono::steady_clock::now();
  if (auto problem = request_problem(request)) return failure(PathStatus::InvalidRequest, *problem);
  const OccupancyGrid& grid = *impl_->grid;

  // The exact field first: it settles blocked and unreachable goals without sampling.
  const GridGeometry& geo = grid.geometry();
  const bool given = request.field != nullptr && request.field->geometry().cols() == geo.cols() &&
                     request.field->geometry().rows() == geo.rows() &&
                     request.field->geometry().resolution_m() == geo.resolution_m() &&
                     request.field->goal_cell() == geo.cell_at(request.goal);
  std::optional<CostToGoField> computed;
  if (!given) computed.emplace(grid, request.goal);
  const CostToGoField& field = given ? *request.field : *computed;
  const PathResult route = follow_field(field, grid, request.start);
  if (!route.found()) {
    PathResult r = route;
    r.planning_s = seconds_since(t0);
    return r;
  }

  auto route_poses = std::make_shared<const std::vector<geometry::Pose2>>(route.poses);
  const bool reverse_too = settings_.curve == CurveModel::ReedsShepp;
  impl_->space->setStateSamplerAllocator([route_poses, reverse_too](const ob::StateSpace* space) {
    return std::make_shared<RouteBiasedSampler>(space, route_poses, reverse_too);
  });
  og::SimpleSetup ss(impl_->space);
  const auto si = ss.getSpaceInformation();
  const auto free_at = [&grid](double x, double y) {
    const auto c = grid.geometry().cell_at({x, y});
    return c && !grid.blocked(*c);
  };
  ss.setStateValidityChecker([free_at](const ob::State* s) {
    const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
    return free_at(se2->getX(), se2->getY());
  });
  // Distances in these spaces are metres along the motion (plus 0.5 per radian of turn in plain
  // SE(2)), so this fraction of the extent is a check at least every motion_step_m.
  // (0.8: the chord between two checked states then stays under the step on curves too.)
  si->setStateValidityCheckingResolution(0.8 * settings_.motion_step_m /
                                         impl_->space->getMaximumExtent());

  ob::ScopedState<ob::SE2StateSpace> start(impl_->space), goal(impl_->space);
  start->setXY(request.start.x, request.start.y);
  // A robot that turns on the spot starts its curves facing along the route (the path's first
  // pose is then the turn in place).
  // Dubins curves are a car's, forward only: they never start with a turn in place.
  const bool spin_first = settings_.turn_in_place_at_start && settings_.curve == CurveModel::ReedsShepp;
  start->setYaw(
      spin_first
          ? route_heading(route.poses, 0,
                          std::max<std::size_t>(
                              1, static_cast<std::size_t>(0.3 / grid.geometry().resolution_m())))
          : request.start.theta);
  goal->setXY(request.goal.x(), request.goal.y());
  goal->setYaw(request.goal_heading ? *request.goal_heading
                                    : arrival_heading(route.poses, request.start.theta));
  impl_->space->enforceBounds(start.get());  // headings into OMPL's [-pi, pi)
  impl_->space->enforceBounds(goal.get());
  ss.setStartAndGoalStates(start, goal, 1e-3);

  auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
  const double res = grid.geometry().resolution_m();
  const geometry::Vec2 goal_xy = request.goal;
  const CostToGoField* f = &field;
  objective->setCostToGoHeuristic([f, goal_xy, res](const ob::State* s, const ob::Goal*) {
    const auto* se2 = s->as<ob::SE2StateSpace::StateType>();
    const geometry::Vec2 p(se2->getX(), se2->getY());
    const double euclid = (goal_xy - p).norm();
    const double grid_bound = f->cost_at(p) / kOctileOverEuclid - 2.0 * res;
    return ob::Cost(std::isfinite(grid_bound) ? std::max(euclid, grid_bound) : euclid);
  });
  objective->setCostThreshold(ob::Cost(settings_.good_enough_ratio * route.length_m));
  ss.setOptimizationObjective(objective);
  ss.setPlanner(make_planner(settings_.planner, si));

  try {
    ss.setup();
    // Most of the budget plans; what is left of it simplifies.
    const double plan_s = 0.8 * request.budget_s;
    std::optional<og::PathGeometric> guided;
    if (settings_.route_guide) {
      guided = route_guided_path(si, route.poses, ss.getProblemDefinition()->getStartState(0),
                                 goal.get(), res, settings_.route_guide_reach_m,
                                 ob::timedPlannerTerminationCondition(plan_s));
    }
    if (!guided) {
      const ob::PlannerStatus solved = ss.solve(
          ob::timedPlannerTerminationCondition(std::max(1e-4, plan_s - seconds_since(t0))));
      if (solved != ob::PlannerStatus::EXACT_SOLUTION) {
        PathResult r =
            failure(PathStatus::NotFound, std::string(settings_.planner) + " found no path in " +
                                              std::to_string(request.budget_s) + " s (" +
                                              solved.asString() + ")");
        r.planning_s = seconds_since(t0);
        return r;
      }
    }
    og::PathGeometric path = guided ? *guided : ss.getSolutionPath();
    if (settings_.simplify) {
      og::PathSimplifier simplifier(si, ss.getGoal(), objective);
      // A guided path has few vertices, most of them needless: dropping those first is cheap and
      // leaves the simplifier's time for the cusps of the first hop.
      if (guided) {
        simplifier.reduceVertices(path);
        simplifier.collapseCloseVertices(path);
      }
      // What is left of the budget, no more: a query that planned up to the budget (a long recon
      // route guided hop by hop) ended 10 ms over it with a fixed fifth for simplifying.
      const double left = request.budget_s - seconds_since(t0);
      if (left > 0.0) simplifier.simplify(path, left);
    }
    PathResult r;
    r.status = PathStatus::Found;
    r.route_guided = guided.has_value();
    // The poses are exactly the states the motion validator checked along each motion (same
    // segment count, same interpolation), so the final check tests what the planner accepted.
    const auto pose_of = [](const ob::State* st) {
      const auto* se2 = st->as<ob::SE2StateSpace::StateType>();
      return geometry::Pose2{se2->getX(), se2->getY(), se2->getYaw()};
    };
    ob::ScopedState<ob::SE2StateSpace> between(impl_->space);
    const auto* reeds_shepp = dynamic_cast<const ob::ReedsSheppStateSpace*>(impl_->space.get());
    const auto* dubins = dynamic_cast<const ob::DubinsStateSpace*>(impl_->space.get());
    if (spin_first) r.poses.push_back(request.start);
    r.poses.push_back(pose_of(path.getState(0)));
    for (std::size_t i = 1; i < path.getStateCount(); ++i) {
      const ob::State* a = path.getState(i - 1);
      const ob::State* b = path.getState(i);
      const int n = std::max(1, static_cast<int>(impl_->space->validSegmentCount(a, b)));
      // The curve spaces compute the segment's curve once (their caching interpolate): one curve
      // per pose made the conversion of a 200 m path cost more than planning it.
      bool first = true;
      ob::ReedsSheppStateSpace::ReedsSheppPath rs_path;
      ob::DubinsStateSpace::DubinsPath dubins_path;
      for (int k = 1; k < n; ++k) {
        const double t = static_cast<double>(k) / n;
        if (reeds_shepp)
          reeds_shepp->interpolate(a, b, t, first, rs_path, between.get());
        else if (dubins)
          dubins->interpolate(a, b, t, first, dubins_path, between.get());
        else
          impl_->space->interpolate(a, b, t, between.get());
        r.poses.push_back(pose_of(between.get()));
      }
      r.poses.push_back(pose_of(b));
    }
    r.length_m = path_length(r.poses);
    r.planning_s = seconds_since(t0);
    if (const auto bad = first_collision(grid, r.poses, settings_.motion_step_m)) {
      return failure(PathStatus::NotFound, "planned path leaves the free space at segment " +
                                               std::to_string(*bad) + "; discarded");
    }
    return r;
  } catch (const ompl::Exception& e) {
    PathResult r = failure(PathStatus::NotFound, std::string("OMPL: ") + e.what());
    r.planning_s = seconds_since(t0);
    return r;
  }
}

double dubins_distance(const geometry::Pose2& a, const geometry::Pose2& b, double turning_radius_m) {
  const auto space = std::make_shared<GuardedDubinsStateSpace>(turning_radius_m);
  ob::ScopedState<ob::SE2StateSpace> from(space), to(space);
  from->setXY(a.x, a.y);
  from->setYaw(a.theta);
  to->setXY(b.x, b.y);
  to->setYaw(b.theta);
  return space->distance(from.get(), to.get());
}

geometry::Pose2 dubins_interpolate(const geometry::Pose2& a, const geometry::Pose2& b, double t,
                                   double turning_radius_m) {
  const auto space = std::make_shared<GuardedDubinsStateSpace>(turning_radius_m);
  ob::ScopedState<ob::SE2StateSpace> from(space), to(space), at(space);
  from->setXY(a.x, a.y);
  from->setYaw(a.theta);
  to->setXY(b.x, b.y);
  to->setYaw(b.theta);
  bool first = true;
  ob::DubinsStateSpace::DubinsPath path;
  space->interpolate(from.get(), to.get(), t, first, path, at.get());
  return {at->getX(), at->getY(), at->getYaw()};
}

namespace {

// OMPL's Benchmark with its experiment filled from our own runs, so its writer does the format.
class LogWriter : public ompl::tools::Benchmark {
 public:
  LogWriter(og::SimpleSetup& setup, const BenchmarkLog& log) : Benchmark(setup, log.experiment) {
    exp_.maxTime = log.max_time_s;
    exp_.maxMem = 0.0;
    exp_.runCount = log.run_count;
    exp_.startTime = ompl::time::now();
    exp_.totalDuration = log.total_duration_s;
    exp_.setupInfo = log.setup_info;
    exp_.seed = log.seed;
    exp_.host = ompl::machine::getHostname();
    exp_.cpuInfo = ompl::machine::getCPUInfo();
    exp_.parameters = log.parameters;
    for (const auto& p : log.planners) {
      PlannerExperiment e;
      e.name = p.name;
      e.runs = p.runs;
      exp_.planners.push_back(std::move(e));
    }
  }
};

}  // namespace

bool write_benchmark_log(std::ostream& out, const BenchmarkLog& log) {
  og::SimpleSetup setup(std::make_shared<ob::SE2StateSpace>());
  const LogWriter writer(setup, log);
  return writer.saveResultsToStream(out);
}

}  // namespace autonomy::behavior
