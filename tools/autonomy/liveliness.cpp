#include "tools/autonomy/liveliness.hpp"

#include <algorithm>
#include <utility>

namespace autonomy::tools {

const char* to_string(LivelinessEvent::Kind kind) {
  switch (kind) {
    case LivelinessEvent::Kind::Heard:
      return "heard";
    case LivelinessEvent::Kind::Silent:
      return "silent";
    case LivelinessEvent::Kind::HeardAgain:
      return "heard_again";
    case LivelinessEvent::Kind::Hung:
      return "hung";
    case LivelinessEvent::Kind::Stopped:
      return "stopped";
    case LivelinessEvent::Kind::Gone:
      return "gone";
  }
  return "?";
}

bool LivelinessRules::watches(const std::string& name) const {
  return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
}

double LivelinessRules::hang_after(const std::string& name) const {
  const auto it = hang_after_by_name.find(name);
  return it == hang_after_by_name.end() ? hang_after_s : it->second;
}

std::vector<LivelinessEvent> LivelinessMonitor::check(ProcessTable& table, int64_t now_ns,
                                                      const std::function<bool(const ProcessKey&)>& is_gone) {
  std::vector<LivelinessEvent> events;
  std::vector<ProcessKey> forgotten;
  auto event = [&](LivelinessEvent::Kind kind, const ProcessView& row, int64_t silent_ns, double limit_s = 0.0) {
    events.push_back({kind, row.key(), row.last, static_cast<double>(silent_ns) / 1e9, limit_s});
  };

  for (const auto& [key, row] : table.rows()) {
    const std::string name = key.name();
    if (!rules_.watches(name)) continue;
    auto [it, fresh] = memos_.try_emplace(key);
    Memo& memo = it->second;
    if (fresh) {
      memo.heard_at_ns = row.heard_at_ns;
      if (row.instance_state == dds::InstanceState::Alive) event(LivelinessEvent::Kind::Heard, row, 0);
    }

    if (row.instance_state == dds::InstanceState::Disposed) {
      event(LivelinessEvent::Kind::Stopped, row, 0);
      forgotten.push_back(key);
      continue;
    }
    if (row.heard_at_ns > memo.heard_at_ns) {  // a heartbeat came since the last look
      if (memo.silent) event(LivelinessEvent::Kind::HeardAgain, row, row.heard_at_ns - memo.heard_at_ns);
      memo = Memo{row.heard_at_ns, false, false};
    }

    const int64_t silence = now_ns - row.heard_at_ns;
    const int64_t silent_after = silent_after_ns(row.last.period_ms);
    const bool is_silent = silence > silent_after || row.instance_state == dds::InstanceState::NoWriters;
    if (!is_silent) continue;
    if (is_gone && is_gone(key)) {
      event(LivelinessEvent::Kind::Gone, row, silence);
      forgotten.push_back(key);
      continue;
    }
    if (!memo.silent) {
      memo.silent = true;
      event(LivelinessEvent::Kind::Silent, row, silence);
    }
    const double limit_s = rules_.hang_after(name);
    const int64_t limit_ns = std::max(static_cast<int64_t>(limit_s * 1e9), silent_after);
    if (limit_s > 0 && !memo.hung && silence >= limit_ns) {
      memo.hung = true;
      event(LivelinessEvent::Kind::Hung, row, silence, limit_s);
    }
  }

  for (const auto& key : forgotten) {
    table.forget(key);
    memos_.erase(key);
  }
  // Rows the table no longer has (forgotten by the caller) take their memos with them.
  for (auto it = memos_.begin(); it != memos_.end();) {
    it = table.rows().count(it->first) ? std::next(it) : memos_.erase(it);
  }
  return events;
}

std::vector<const ProcessView*> LivelinessMonitor::silent(const ProcessTable& table) const {
  std::vector<const ProcessView*> out;
  for (const auto& [key, memo] : memos_) {
    if (!memo.silent) continue;
    const auto it = table.rows().find(key);
    if (it != table.rows().end()) out.push_back(&it->second);
  }
  return out;
}

}  // namespace autonomy::tools
