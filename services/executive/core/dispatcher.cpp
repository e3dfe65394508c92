#include "dispatcher.hpp"

#include <algorithm>

namespace autonomy::executive {

Dispatcher::Dispatcher(planner::FlexiblePlan plan, DispatchableNetwork net, Time origin_time)
    : plan_(std::move(plan)), net_(std::move(net)) {
  const std::size_t n = net_.names.size();
  out_.resize(n);
  in_.resize(n);
  for (std::size_t e = 0; e < net_.edges.size(); ++e) {
    out_[net_.edges[e].from].push_back(e);
    in_[net_.edges[e].to].push_back(e);
  }
  lb_.assign(n, -kUnbounded);
  ub_.assign(n, kUnbounded);
  for (std::size_t p = 0; p < n; ++p) {
    if (net_.earliest[p] > -kUnbounded) lb_[p] = origin_time + net_.earliest[p];
    if (net_.latest[p] < kUnbounded) ub_[p] = origin_time + net_.latest[p];
  }
  at_.assign(n, 0);
  done_.assign(n, false);
  observed_.assign(n, false);
  reported_.assign(n, false);
  held_.assign(n, false);
  for (const planner::PlanTimeline& line : plan_.timelines)
    if (!line.tokens.empty() && line.tokens.back() < plan_.tokens.size())
      held_[tp(line.tokens.back(), false)] = true;
  if (plan_.horizon > 0) hold_until_ = origin_time + plan_.horizon;
  execute(0, origin_time);
  pending_.clear();
}

void Dispatcher::set_observed(std::size_t token, bool start, bool observed) {
  observed_[tp(token, start)] = observed;
}

bool Dispatcher::enabled(std::size_t p) const {
  // A negative edge p->q (time(q) - time(p) <= w < 0) says q precedes p. With w = 0, q is
  // not after p: a controllable q then executes in the same pass, but an observed q (a turn's
  // end) is waited for, or executing p would force the world's hand.
  for (std::size_t e : out_[p]) {
    const DistanceEdge& d = net_.edges[e];
    if (!done_[d.to] && (d.weight < 0 || (d.weight == 0 && observed_[d.to]))) return false;
  }
  return true;
}

void Dispatcher::violation(std::size_t p, Time t, std::string reason) {
  broken_ = true;
  pending_.push_back({DispatchEvent::Kind::kViolation, net_.token[p], t,
                      net_.names[p] + ": " + std::move(reason)});
}

void Dispatcher::execute(std::size_t p, Time t) {
  done_[p] = true;
  at_[p] = t;
  if (p != 0)
    pending_.push_back(
        {net_.is_start[p] ? DispatchEvent::Kind::kStarted : DispatchEvent::Kind::kEnded,
         net_.token[p], t, ""});
  // Propagate to neighbours only (the dispatchable form makes this enough).
  for (std::size_t e : out_[p]) {
    const DistanceEdge& d = net_.edges[e];
    if (!done_[d.to]) ub_[d.to] = std::min(ub_[d.to], t + d.weight);
  }
  for (std::size_t e : in_[p]) {
    const DistanceEdge& d = net_.edges[e];
    if (!done_[d.from]) lb_[d.from] = std::max(lb_[d.from], t - d.weight);
  }
  for (const auto* list : {&out_[p], &in_[p]})
    for (std::size_t e : *list) {
      std::size_t q = net_.edges[e].from == p ? net_.edges[e].to : net_.edges[e].from;
      if (!done_[q] && !reported_[q] && lb_[q] > ub_[q]) {
        reported_[q] = true;
        violation(q, t,
                  "window emptied by " + net_.names[p] + " at " + std::to_string(t) + " (lb " +
                      std::to_string(lb_[q]) + " > ub " + std::to_string(ub_[q]) + ")");
      }
    }
}

void Dispatcher::observe(std::size_t token, bool start, Time time) {
  std::size_t p = tp(token, start);
  if (done_[p]) return;  // a repeated observation changes nothing
  if (time < lb_[p] || time > ub_[p])
    violation(p, time,
              "observed at " + std::to_string(time) + " outside [" + std::to_string(lb_[p]) + ", " +
                  std::to_string(ub_[p]) + "]");
  execute(p, time);
}

std::vector<DispatchEvent> Dispatcher::step(Time now) {
  const std::size_t n = net_.names.size();
  // Each pass executes at least one timepoint or stops, so at most n passes.
  for (std::size_t pass = 0; pass < n; ++pass) {
    bool progress = false;
    for (std::size_t p = 1; p < n; ++p) {
      Time when = held_[p] ? std::max(lb_[p], std::min(ub_[p], hold_until_)) : lb_[p];
      if (done_[p] || observed_[p] || when > now || ub_[p] < now || !enabled(p)) continue;
      execute(p, now);
      progress = true;
    }
    if (!progress) break;
  }
  for (std::size_t p = 1; p < n; ++p)
    if (!done_[p] && !reported_[p] && ub_[p] < now) {
      reported_[p] = true;
      violation(p, now,
                std::string(observed_[p] ? "not observed" : "not executable") + " by its bound " +
                    std::to_string(ub_[p]));
    }
  std::vector<DispatchEvent> events;
  events.swap(pending_);
  return events;
}

void Dispatcher::start() {
  pending_ = step(at_[0]);
}

bool Dispatcher::finished() const {
  return std::all_of(done_.begin(), done_.end(), [](bool b) { return b; });
}

}  // namespace autonomy::executive
