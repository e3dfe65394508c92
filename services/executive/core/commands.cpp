#include "commands.hpp"

#include <algorithm>
#include <cctype>

namespace autonomy::executive {
namespace {

// "?N" -> N, or -1 when the argument is a literal.
long parameter_index(const std::string& a) {
  if (a.size() < 2 || a[0] != '?') return -1;
  if (!std::all_of(a.begin() + 1, a.end(), [](unsigned char c) { return std::isdigit(c); }))
    return -2;
  return std::stol(a.substr(1));
}

}  // namespace

bool CommandMap::add(CommandRule rule, std::string* error) {
  auto fail = [&](const std::string& why) {
    if (error) *error = "command rule " + rule.timeline + " == " + rule.predicate + ": " + why;
    return false;
  };
  if (rule.timeline.empty() || rule.predicate.empty()) return fail("timeline and predicate needed");
  if (rule.device.empty()) return fail("device needed");
  if (rule.command.empty() && rule.expect_mode.empty())
    return fail("a command or an expected mode needed");
  if (rule.confirm_timeout <= 0) return fail("confirm_timeout must be positive");
  for (const std::string& a : rule.arguments)
    if (parameter_index(a) == -2) return fail("argument '" + a + "' is not ?<number>");
  if (rule_for_key(rule.timeline, rule.predicate)) return fail("declared twice");
  rules_.push_back(std::move(rule));
  return true;
}

const CommandRule* CommandMap::rule_for_key(const std::string& timeline,
                                            const std::string& predicate) const {
  for (const CommandRule& r : rules_)
    if (r.timeline == timeline && r.predicate == predicate) return &r;
  return nullptr;
}

const CommandRule* CommandMap::rule_for(const planner::PlanToken& token) const {
  return rule_for_key(token.timeline(), token.predicate);
}

std::optional<DeviceCommand> CommandMap::command_for(const planner::PlanToken& token,
                                                     std::size_t index, Time now,
                                                     std::string* error) const {
  const CommandRule* r = rule_for(token);
  if (!r || r->command.empty()) return std::nullopt;
  DeviceCommand c{r->device, r->command, {}, index, now};
  for (const std::string& a : r->arguments) {
    long i = parameter_index(a);
    if (i < 0) {
      c.arguments.push_back(a);
    } else if (static_cast<std::size_t>(i) < token.parameters.size()) {
      c.arguments.push_back(token.parameters[i]);
    } else {
      if (error)
        *error = "token " + std::to_string(token.id) + " (" + token.predicate +
                 ") has no parameter " + a;
      return std::nullopt;
    }
  }
  return c;
}

void CommandTracker::sent(const DeviceCommand& command, Time timeout) {
  pending_.push_back({command, command.sent + timeout});
}

bool CommandTracker::confirm(const std::string& device, const std::string& command) {
  auto it = std::find_if(pending_.begin(), pending_.end(), [&](const Pending& p) {
    return p.command.device == device && p.command.command == command;
  });
  if (it == pending_.end()) return false;
  pending_.erase(it);
  return true;
}

bool CommandTracker::awaiting(const std::string& device) const {
  return std::any_of(pending_.begin(), pending_.end(),
                     [&](const Pending& p) { return p.command.device == device; });
}

std::vector<DeviceCommand> CommandTracker::expire(Time now) {
  std::vector<DeviceCommand> late;
  auto keep = std::stable_partition(pending_.begin(), pending_.end(),
                                    [&](const Pending& p) { return p.deadline >= now; });
  for (auto it = keep; it != pending_.end(); ++it) late.push_back(it->command);
  pending_.erase(keep, pending_.end());
  return late;
}

}  // namespace autonomy::executive
