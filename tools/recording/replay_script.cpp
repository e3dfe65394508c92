#include "tools/recording/replay_script.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace autonomy::recording {

namespace {

void by_log_time(std::vector<RecordedSample>& samples) {
  std::stable_sort(samples.begin(), samples.end(),
                   [](const RecordedSample& a, const RecordedSample& b) { return a.log_time < b.log_time; });
}

// How many members of a and b agree, for picking the fresh sample a recorded one is nearest to.
std::size_t agreement(const Json& a, const Json& b) {
  if (a.is_object() && b.is_object()) {
    std::size_t n = 0;
    for (auto it = a.begin(); it != a.end(); ++it)
      if (b.contains(it.key())) n += agreement(it.value(), b.at(it.key()));
    return n;
  }
  return a == b ? 1 : 0;
}

}  // namespace

Json world_content(Json value) {
  if (value.is_object()) {
    value.erase("world_id");
    for (auto& [key, member] : value.items()) member = world_content(std::move(member));
  } else if (value.is_array()) {
    for (auto& element : value) element = world_content(std::move(element));
  }
  return value;
}

std::string OutputMismatch::describe() const {
  std::ostringstream out;
  out << topic << " at tick " << tick << ": ";
  if (fresh.empty()) {
    out << "the replayed world published nothing on this topic for this tick; recorded " << recorded.dump();
    return out.str();
  }
  const Json* nearest = &fresh.front();
  for (const auto& f : fresh)
    if (agreement(recorded, f) > agreement(recorded, *nearest)) nearest = &f;
  out << "no replayed sample equals the recorded one; against the nearest of " << fresh.size() << ":";
  std::size_t shown = 0;
  for (const auto& op : Json::diff(recorded, *nearest)) {
    if (++shown > 8) {
      out << " ...";
      break;
    }
    const std::string path = op.value("path", "");
    Json recorded_value = nullptr;
    if (const Json::json_pointer p(path); recorded.contains(p)) recorded_value = recorded.at(p);
    out << " " << path << " recorded " << recorded_value.dump() << ", replayed "
        << (op.contains("value") ? op.at("value").dump() : std::string("(absent)")) << ";";
  }
  return out.str();
}

ReplayScript::ReplayScript(std::vector<RecordedSample> inputs, std::vector<RecordedSample> outputs,
                           std::vector<RecordedSample> clocks) {
  by_log_time(inputs);
  by_log_time(outputs);
  std::vector<std::pair<uint64_t, int64_t>> clock_at;  // (publish time, tick), by publish time
  std::set<int64_t> ticks;
  for (const auto& c : clocks)
    if (c.tick) {
      clock_at.emplace_back(c.publish_time, *c.tick);
      ticks.insert(*c.tick);
    }
  std::sort(clock_at.begin(), clock_at.end());
  clock_ticks_.assign(ticks.begin(), ticks.end());
  // The tick the recorded world showed when a sample was written.
  auto shown_at = [&](uint64_t publish_time) {
    auto it = std::upper_bound(clock_at.begin(), clock_at.end(), std::make_pair(publish_time, INT64_MAX));
    return it == clock_at.begin() ? kAtStart : std::prev(it)->second;
  };

  // Each participant's acks in the order written: a repeated one is due at the next one's tick.
  std::map<std::string, std::vector<std::size_t>> acks_of;
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (inputs[i].topic == kLockstepAckTopic && inputs[i].tick)
      acks_of[inputs[i].value.value("participant", "")].push_back(i);
  std::vector<std::optional<int64_t>> woke_at(inputs.size());
  for (const auto& [participant, acks] : acks_of)
    for (std::size_t k = 1; k < acks.size(); ++k) {
      const int64_t tick = *inputs[acks[k]].tick;
      if (tick != *inputs[acks[k - 1]].tick) continue;
      for (std::size_t next = k + 1; next < acks.size(); ++next)
        if (*inputs[acks[next]].tick > tick) {
          woke_at[acks[k]] = *inputs[acks[next]].tick;
          break;
        }
    }

  struct Ordered {
    ReplayInput input;
    bool ack = false;
    std::size_t order = 0;
  };
  std::vector<Ordered> ordered;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    auto& s = inputs[i];
    const bool ack = s.topic == kLockstepAckTopic;
    const int64_t due = woke_at[i] ? *woke_at[i] : s.tick ? *s.tick : shown_at(s.publish_time);
    ordered.push_back({{due, s.topic, std::move(s.cdr)}, ack, i});
  }
  std::stable_sort(ordered.begin(), ordered.end(), [](const Ordered& a, const Ordered& b) {
    return std::tie(a.input.due, a.ack, a.order) < std::tie(b.input.due, b.ack, b.order);
  });
  for (auto& o : ordered) inputs_.push_back(std::move(o.input));

  for (auto& s : outputs) {
    if (!s.tick) continue;
    // After the last clock: due at the end (checked against whatever came).
    outputs_.push_back({next_clock_after(*s.tick).value_or(INT64_MAX), s.topic, *s.tick, world_content(std::move(s.value))});
  }
  std::stable_sort(outputs_.begin(), outputs_.end(),
                   [](const Expected& a, const Expected& b) { return a.due < b.due; });
  if (!clock_ticks_.empty()) last_tick_ = clock_ticks_.back();
  if (!inputs_.empty()) last_tick_ = std::max(last_tick_, inputs_.back().due);
  for (const auto& e : outputs_) last_tick_ = std::max(last_tick_, e.tick);
}

std::optional<int64_t> ReplayScript::next_clock_after(int64_t tick) const {
  auto it = std::upper_bound(clock_ticks_.begin(), clock_ticks_.end(), tick);
  if (it == clock_ticks_.end()) return std::nullopt;
  return *it;
}

void ReplayScript::fresh_output(const std::string& topic, int64_t tick, Json value) {
  fresh_[{topic, tick}].push_back(world_content(std::move(value)));
}

std::optional<OutputMismatch> ReplayScript::check_due_by(int64_t clock) {
  while (next_unchecked_ < outputs_.size() && outputs_[next_unchecked_].due <= clock) {
    const Expected& e = outputs_[next_unchecked_];
    auto& fresh = fresh_[{e.topic, e.tick}];
    const auto twin = std::find(fresh.begin(), fresh.end(), e.value);
    if (twin == fresh.end()) return OutputMismatch{e.topic, e.tick, e.value, fresh};
    // Kept: a recorded repeat of the same sample matches it again (see the header).
    ++matched_;
    ++next_unchecked_;
  }
  return std::nullopt;
}

std::map<std::string, std::size_t> ReplayScript::outputs_by_topic() const {
  std::map<std::string, std::size_t> out;
  for (const auto& e : outputs_) ++out[e.topic];
  return out;
}

std::optional<std::string> unacknowledged_commands(const std::vector<RecordedSample>& inputs) {
  std::set<std::string> participants;
  std::set<std::pair<std::string, int64_t>> acked;
  for (const auto& s : inputs) {
    const auto& v = s.value;
    if (!v.is_object() || !v.contains("participant") || !v.at("participant").is_string()) continue;
    const auto name = v.at("participant").get<std::string>();
    if (s.topic == kLockstepRegistrationTopic && v.value("active", false)) participants.insert(name);
    if (s.topic == kLockstepAckTopic && s.tick) acked.insert({name, *s.tick});
  }
  std::size_t missing = 0;
  const RecordedSample* first = nullptr;
  for (const auto& s : inputs) {
    const auto& v = s.value;
    if (s.topic == kLockstepAckTopic || !s.tick || !v.is_object() || !v.contains("source") || !v.at("source").is_string())
      continue;
    const auto source = v.at("source").get<std::string>();
    if (!participants.count(source) || acked.count({source, *s.tick})) continue;
    if (!first || s.publish_time < first->publish_time) first = &s;
    ++missing;
  }
  if (!first) return std::nullopt;
  return std::to_string(missing) + " recorded command(s) have no acknowledgement of their tick from their lockstep " +
         "participant in the file (the first: " + first->topic + " from " + first->value.at("source").get<std::string>() +
         " at tick " + std::to_string(*first->tick) + ")";
}

}  // namespace autonomy::recording
