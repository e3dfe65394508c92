#pragma once
// Runs a mission (a graph of states, Wagner & Arkin 2003 "plans in serial") one control step at a
// time. Pure: the caller brings the perception with its time; the executor keeps only the current
// state, when it was entered and that state's schema blend. No clock, no threads, no I/O.
//
// Each step(p):
//  1. On the first call, enters the initial state (event Started).
//  2. Checks the current state's transitions in order; the first trigger that fires moves to its
//     target (event Transition, with the trigger's reason) and the new state's transitions are
//     checked at once with the same perception, so a robot that enters "wait" while its link is
//     already back leaves it in the same step. The chain is capped at the number of states, which
//     bounds any cycle of always-firing triggers (the executor then stays where the cap left it).
//  3. Runs the state's behavior:
//       GoTo:   move_to_goal (towards the state's goal), avoid_obstacles, noise, the team schemas,
//               and plan advice from the state's plan set with its selection mode, each with the
//               state's gain. Static selection is made on entering the state (event PlanChosen);
//               if no plan has a route from there, it is retried every step (event NoViablePlan
//               once) and the plan term is absent meanwhile.
//       Wander: noise, avoid_obstacles and the team schemas (the paper's cure for the deadlock).
//       Wait:   zero velocity until a transition fires.
//       Stop:   zero velocity; the mission is finished (event Finished) and stays so.
//     The blend's vector becomes a VelocityCommand for the perception's kinematics and limits.
//
// Time in a state is p.time_s minus the entry time: Timeout triggers count from entry, and a
// state re-entered later starts counting again.
#include "services/behavior/core/mission/mission_spec.hpp"
#include "services/behavior/core/mission/perceptual_trigger.hpp"
#include "services/behavior/core/mission/plan_library.hpp"
#include "services/behavior/core/schemas/perception.hpp"
#include "services/behavior/core/schemas/plan_advice.hpp"
#include "services/behavior/core/schemas/schema_blend.hpp"
#include "services/behavior/core/velocity_command.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

struct MissionEvent {
  enum class Kind {
    Started,       // state = the initial state
    Transition,    // from -> state, because `reason`
    PlanChosen,    // static selection in `state` chose plan `plan`
    NoViablePlan,  // static selection in `state` found no plan with a route; retried each step
    Finished,      // entered a Stop state
    Resumed,       // resume(): continues in `state`, entered earlier by another executor; `reason` says why
  };
  Kind kind = Kind::Started;
  double time_s = 0.0;
  std::string state;
  std::string from;    // Transition only
  std::string reason;  // Transition: the trigger's words; PlanChosen: the plan's name
  std::string to_string() const;  // one line for logs
};

struct MissionStep {
  std::string state;  // the current state after this step
  BehaviorSpec::Kind behavior = BehaviorSpec::Kind::Stop;
  geometry::Vec2 velocity = geometry::Vec2::Zero();  // desired, world frame, m/s
  VelocityCommand command;
  BlendResult blend;                     // the votes behind `velocity`, for logs and plots
  std::optional<PlanSelection> plan;     // which plan advised, when the state follows a plan set
  bool finished = false;
  std::vector<MissionEvent> events;      // in the order they happened during this step
};

// Where a mission is, enough for another executor to continue it (behavior --journal): the
// state, when it was entered (Timeout triggers count from then), and the plan static selection
// chose there.
struct MissionProgress {
  std::string state;
  double entered_at_s = 0.0;
  std::string plan;  // "" when the state follows no statically chosen plan (or none had a route yet)
};

struct MissionExecutorOptions {
  std::uint64_t noise_seed = 0;  // per robot: e.g. the scenario seed mixed with the robot id
  UnicycleSteering steering;
};

class MissionExecutor {
 public:
  // `plans` must hold every plan set a GoTo state names (build_plan_library). Throws
  // std::invalid_argument when the spec is inconsistent (unknown initial or target state, missing
  // plan set, invalid schema parameters); the loader reports such mistakes with file positions
  // first, so this is a guard for hand-built specs.
  MissionExecutor(MissionSpec spec, PlanLibrary plans, MissionExecutorOptions options = {});
  ~MissionExecutor();
  MissionExecutor(MissionExecutor&&) noexcept;
  MissionExecutor& operator=(MissionExecutor&&) noexcept;

  [[nodiscard]] MissionStep step(const Perception& p);

  // Instead of starting in the initial state: continues where `progress` says, as if this executor
  // had entered progress.state at progress.entered_at_s and chosen progress.plan there (chosen
  // again from p's position when the state's plan set has no such plan). Returns [Resumed, with
  // `reason`], then any plan choice made anew (PlanChosen or NoViablePlan); a Stop state stays
  // finished without a second Finished. The next step() goes on from there. Throws
  // std::invalid_argument for a state the mission does not have, std::logic_error after a step.
  [[nodiscard]] std::vector<MissionEvent> resume(const MissionProgress& progress, const Perception& p,
                                                 const std::string& reason);
  // nullopt before the first step (or resume).
  std::optional<MissionProgress> progress() const;

  // Before the first step: the initial state's name.
  const std::string& state() const;
  bool finished() const;
  // The current state's goal (GoTo states only).
  std::optional<geometry::Vec2> goal() const;
  const MissionSpec& spec() const { return spec_; }

 private:
  struct CompiledState;
  struct Active;

  // preferred_plan: a static choice made before (resume), kept when the plan set still has it.
  void enter(std::size_t index, const Perception& p, std::vector<MissionEvent>& events,
             const std::string& preferred_plan = "");
  void try_static_choice(const Perception& p, std::vector<MissionEvent>& events, const std::string& preferred_plan = "");

  MissionSpec spec_;
  PlanLibrary plans_;
  MissionExecutorOptions options_;
  std::vector<CompiledState> states_;
  std::size_t initial_ = 0;
  std::unique_ptr<Active> active_;  // nullptr before the first step
};

}  // namespace autonomy::behavior
