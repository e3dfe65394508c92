#pragma once
// Perceptual triggers (Wagner & Arkin 2003, section 2.4; MissionLab's triggers): conditions on
// what the robot perceives that move a mission from one state to the next.
//
// All triggers are level-triggered and stateless: fires() looks at the current perception and the
// time spent in the current state, nothing else, so a trigger that fires keeps firing while its
// condition holds (LostContact holds for as long as the link is down). Edge behaviour comes from
// the mission graph: "lost contact -> wait; in wait, contact restored -> go on".
//
// Contact: a teammate counts as out of contact when it is absent from the perception or its
// in_contact flag is false. LostContact("") fires when any of the mission's teammates is out of
// contact; ContactRestored("") when all of them are in contact.
#include "services/behavior/core/mission/mission_spec.hpp"
#include "services/behavior/core/schemas/perception.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace autonomy::behavior {

struct TriggerContext {
  const Perception& perception;
  double time_in_state_s = 0.0;
  std::optional<geometry::Vec2> goal;  // the state's goal, if it has one
  double tolerance_m = 0.0;            // the state's goal tolerance
  const std::vector<std::string>& team;  // the mission's teammates
};

class PerceptualTrigger {
 public:
  virtual ~PerceptualTrigger() = default;
  // nullopt: does not fire. Otherwise the reason, in words, for the transition event
  // ("lost contact with r2", "30 s in state", ...).
  [[nodiscard]] virtual std::optional<std::string> fires(const TriggerContext& c) const = 0;
};

// Builds the trigger a spec describes. Specs are validated by the loader; here an AllOf or AnyOf
// without children and a Timeout of <= 0 s (or not finite) never fire. Never returns nullptr.
[[nodiscard]] std::unique_ptr<PerceptualTrigger> make_trigger(const TriggerSpec& spec);

}  // namespace autonomy::behavior
