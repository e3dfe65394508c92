#include "services/behavior/core/mission/contact_judge.hpp"

#include <cmath>
#include <stdexcept>

namespace autonomy::behavior {

ContactJudge::ContactJudge(ContactJudgeSettings settings) : settings_(settings) {
  if (!(settings_.loss_after_s >= 0.0 && std::isfinite(settings_.loss_after_s)) ||
      !(settings_.restore_after_s >= 0.0 && std::isfinite(settings_.restore_after_s))) {
    throw std::invalid_argument("contact judge delays must be finite and not negative");
  }
}

bool ContactJudge::update(const std::string& teammate, double time_s, bool link_up) {
  auto [it, is_new] = tracks_.try_emplace(teammate);
  Track& t = it->second;
  if (is_new) {
    t = {link_up, link_up, time_s};
    return t.judged;
  }
  if (link_up != t.raw) {
    t.raw = link_up;
    t.raw_since_s = time_s;
  }
  const double held = time_s - t.raw_since_s;
  if (t.judged && !t.raw && held >= settings_.loss_after_s) t.judged = false;
  if (!t.judged && t.raw && held >= settings_.restore_after_s) t.judged = true;
  return t.judged;
}

}  // namespace autonomy::behavior
