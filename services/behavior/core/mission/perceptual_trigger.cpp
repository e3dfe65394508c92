#include "services/behavior/core/mission/perceptual_trigger.hpp"

#include <cmath>
#include <sstream>
#include <utility>

namespace autonomy::behavior {

namespace {

std::string trigger_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool in_contact(const Perception& p, const std::string& id) {
  const TeammateState* t = p.teammate(id);
  return t != nullptr && t->in_contact;
}

class AtGoalTrigger final : public PerceptualTrigger {
 public:
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (!c.goal) return std::nullopt;
    const double d = (*c.goal - c.perception.pose.position()).norm();
    if (!(d <= c.tolerance_m)) return std::nullopt;
    return "at goal (" + trigger_number(c.goal->x()) + ", " + trigger_number(c.goal->y()) + ") within " +
           trigger_number(c.tolerance_m) + " m";
  }
};

class InAreaTrigger final : public PerceptualTrigger {
 public:
  explicit InAreaTrigger(Area area) : area_(std::move(area)) {}
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (!area_.contains(c.perception.pose.position())) return std::nullopt;
    if (area_.shape == Area::Shape::Circle) {
      return "in area: within " + trigger_number(area_.circle.radius) + " m of (" +
             trigger_number(area_.circle.center.x()) + ", " + trigger_number(area_.circle.center.y()) + ")";
    }
    return "in area [" + trigger_number(area_.rect.min_x) + ", " + trigger_number(area_.rect.max_x) + "] x [" +
           trigger_number(area_.rect.min_y) + ", " + trigger_number(area_.rect.max_y) + "]";
  }

 private:
  Area area_;
};

class LostContactTrigger final : public PerceptualTrigger {
 public:
  explicit LostContactTrigger(std::string teammate) : teammate_(std::move(teammate)) {}
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (!teammate_.empty()) {
      if (in_contact(c.perception, teammate_)) return std::nullopt;
      return "lost contact with " + teammate_;
    }
    for (const std::string& id : c.team) {
      if (!in_contact(c.perception, id)) return "lost contact with " + id;
    }
    return std::nullopt;
  }

 private:
  std::string teammate_;
};

class ContactRestoredTrigger final : public PerceptualTrigger {
 public:
  explicit ContactRestoredTrigger(std::string teammate) : teammate_(std::move(teammate)) {}
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (!teammate_.empty()) {
      if (!in_contact(c.perception, teammate_)) return std::nullopt;
      return "contact restored with " + teammate_;
    }
    for (const std::string& id : c.team) {
      if (!in_contact(c.perception, id)) return std::nullopt;
    }
    return std::string("contact restored with all teammates");
  }

 private:
  std::string teammate_;
};

class TimeoutTrigger final : public PerceptualTrigger {
 public:
  explicit TimeoutTrigger(double seconds) : seconds_(seconds) {}
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (!(std::isfinite(seconds_) && seconds_ > 0.0) || !(c.time_in_state_s >= seconds_)) {
      return std::nullopt;
    }
    return "timeout: " + trigger_number(seconds_) + " s in state";
  }

 private:
  double seconds_;
};

class CombinedTrigger final : public PerceptualTrigger {
 public:
  CombinedTrigger(bool all, std::vector<std::unique_ptr<PerceptualTrigger>> children)
      : all_(all), children_(std::move(children)) {}
  std::optional<std::string> fires(const TriggerContext& c) const override {
    if (children_.empty()) return std::nullopt;
    std::string reasons;
    for (const auto& child : children_) {
      auto reason = child->fires(c);
      if (all_ && !reason) return std::nullopt;
      if (!all_ && reason) return reason;
      if (reason) reasons += (reasons.empty() ? "" : " and ") + *reason;
    }
    if (!all_) return std::nullopt;
    return reasons;
  }

 private:
  bool all_;
  std::vector<std::unique_ptr<PerceptualTrigger>> children_;
};

}  // namespace

std::unique_ptr<PerceptualTrigger> make_trigger(const TriggerSpec& spec) {
  using Kind = TriggerSpec::Kind;
  switch (spec.kind) {
    case Kind::AtGoal: return std::make_unique<AtGoalTrigger>();
    case Kind::InArea: return std::make_unique<InAreaTrigger>(spec.area);
    case Kind::LostContact: return std::make_unique<LostContactTrigger>(spec.teammate);
    case Kind::ContactRestored: return std::make_unique<ContactRestoredTrigger>(spec.teammate);
    case Kind::Timeout: return std::make_unique<TimeoutTrigger>(spec.seconds);
    case Kind::AllOf:
    case Kind::AnyOf: {
      std::vector<std::unique_ptr<PerceptualTrigger>> children;
      for (const TriggerSpec& child : spec.children) children.push_back(make_trigger(child));
      return std::make_unique<CombinedTrigger>(spec.kind == Kind::AllOf, std::move(children));
    }
  }
  return std::make_unique<TimeoutTrigger>(0.0);  // unreachable; never fires
}

}  // namespace autonomy::behavior
