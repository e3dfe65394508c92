#include "tools/courier_plot/courier_story.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>

namespace autonomy::courier_plot {

namespace {

const std::set<std::string>& step_kinds() {
  static const std::set<std::string> kinds{"loaded",      "unloaded",    "door_closed",
                                           "door_opened", "failed_over", "opportunity_taken",
                                           "returning",   "goal_blocked"};
  return kinds;
}

// Words of a sentence: names like job-1, letter-red, A-120 stay whole.
std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::string w;
  for (char c : text + " ") {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') {
      w += c;
    } else if (!w.empty()) {
      out.push_back(w);
      w.clear();
    }
  }
  return out;
}

std::string first_word(const std::string& text) {
  auto w = words(text);
  return w.empty() ? "" : w.front();
}

// The job a sentence is about: the word after "job", or "".
std::string job_of(const std::string& text) {
  auto w = words(text);
  for (size_t i = 0; i + 1 < w.size(); ++i)
    if (w[i] == "job") return w[i + 1];
  return "";
}

}  // namespace

std::string without_clock(const std::string& text) {
  static const std::regex trailing(R"(( \(\d\d:\d\d:\d\d\)| at \d\d:\d\d:\d\d)$)");
  return std::regex_replace(text, trailing, "");
}

std::vector<Step> numbered_steps(const std::vector<CourierEvent>& events,
                                 const std::optional<geometry::Vec2>& start,
                                 const std::string& start_robot) {
  std::vector<Step> steps;
  if (start) {
    Step s;
    s.number = 1;
    s.has_position = true;
    s.position = *start;
    s.lines.push_back(
        {events.empty() ? "" : events.front().time, "start", start_robot + " starts"});
    steps.push_back(s);
  }
  long last_tick = -1;
  for (const auto& e : events) {
    if (!step_kinds().count(e.kind)) continue;
    if (steps.empty() || e.tick != last_tick || steps.back().lines.front().kind == "start") {
      Step s;
      s.number = static_cast<int>(steps.size()) + 1;
      // The robot the sentence names, else the first one listed.
      for (const auto& w : words(e.text))
        if (e.robots.count(w)) {
          s.position = e.robots.at(w);
          s.has_position = true;
          break;
        }
      if (!s.has_position && !e.robots.empty()) {
        s.position = e.robots.begin()->second;
        s.has_position = true;
      }
      steps.push_back(s);
    }
    last_tick = e.tick;
    steps.back().lines.push_back({e.time, e.kind, without_clock(e.text)});
  }
  return steps;
}

const char* phase_name(Phase p) {
  switch (p) {
    case Phase::Waiting:
      return "waiting";
    case Phase::Carried:
      return "carried";
    case Phase::Opportunistic:
      return "opportunistic";
    case Phase::Returning:
      return "returning";
  }
  return "?";
}

Timeline job_timeline(const std::vector<CourierEvent>& events) {
  Timeline t;
  if (events.empty()) return t;
  t.start_s = events.front().sim_s;
  t.end_s = events.back().sim_s;
  t.clock_offset_s =
      static_cast<double>(*clock_seconds(events.front().time)) - std::floor(events.front().sim_s);

  // Which object belongs to which job: objects are the first word of loaded/unloaded sentences;
  // a sentence about a job that names an object ties them ("job job-1 delivered ... (letter-red)").
  std::set<std::string> objects;
  for (const auto& e : events)
    if (e.kind == "loaded" || e.kind == "unloaded") objects.insert(first_word(e.text));
  std::map<std::string, std::string> job_of_object;
  std::map<std::string, size_t> row_of_job;
  auto row = [&](const std::string& id) -> JobRow& {
    auto it = row_of_job.find(id);
    if (it == row_of_job.end()) {
      it = row_of_job.emplace(id, t.jobs.size()).first;
      t.jobs.push_back({id, "", {}, "unfinished", false});
    }
    return t.jobs[it->second];
  };
  for (const auto& e : events) {
    const std::string job = job_of(e.text);
    if (job.empty()) continue;
    JobRow& r = row(job);
    for (const auto& w : words(e.text))
      if (objects.count(w) && !job_of_object.count(w) && r.object.empty()) {
        job_of_object[w] = job;
        r.object = w;
      }
  }
  // Objects no sentence tied: to the accepted jobs still without one, in order.
  for (const auto& e : events) {
    if (e.kind != "loaded") continue;
    const std::string object = first_word(e.text);
    if (job_of_object.count(object)) continue;
    for (auto& r : t.jobs)
      if (r.object.empty()) {
        r.object = object;
        job_of_object[object] = r.id;
        break;
      }
  }

  // Phases, opened and closed by the events in order; what is open at the end runs to the end.
  std::map<std::string, std::map<Phase, double>> open;  // job -> phase -> since
  auto begin = [&](const std::string& job, Phase p, double at) {
    if (!open[job].count(p)) open[job][p] = at;
  };
  auto end = [&](const std::string& job, Phase p, double at) {
    auto it = open[job].find(p);
    if (it == open[job].end()) return;
    row(job).bars.push_back({p, it->second, at});
    open[job].erase(it);
  };
  for (const auto& e : events) {
    std::string job = job_of(e.text);
    if (e.kind == "loaded" || e.kind == "unloaded") {
      auto it = job_of_object.find(first_word(e.text));
      if (it == job_of_object.end()) continue;
      job = it->second;
    }
    if (e.kind == "door_closed" || e.kind == "door_opened") {
      t.doors.push_back({e.sim_s, first_word(e.text), e.kind == "door_opened"});
      continue;
    }
    if (job.empty()) continue;
    if (e.kind == "accepted") {
      row(job);
      begin(job, Phase::Waiting, e.sim_s);
    } else if (e.kind == "loaded") {
      end(job, Phase::Waiting, e.sim_s);
      begin(job, Phase::Carried, e.sim_s);
    } else if (e.kind == "unloaded") {
      end(job, Phase::Carried, e.sim_s);
      end(job, Phase::Returning, e.sim_s);
      end(job, Phase::Opportunistic, e.sim_s);
    } else if (e.kind == "failed_over") {
      begin(job, Phase::Opportunistic, e.sim_s);
    } else if (e.kind == "opportunity_taken") {
      end(job, Phase::Opportunistic, e.sim_s);
    } else if (e.kind == "returning") {
      end(job, Phase::Opportunistic, e.sim_s);
      end(job, Phase::Carried, e.sim_s);
      begin(job, Phase::Returning, e.sim_s);
    } else if (e.kind == "finished") {
      JobRow& r = row(job);
      std::string outcome = without_clock(e.text);
      const std::string prefix = "job " + job + " ";
      if (outcome.rfind(prefix, 0) == 0) outcome = outcome.substr(prefix.size());
      r.outcome = outcome;
      r.failed = outcome.rfind("failed", 0) == 0 || outcome.rfind("cancelled", 0) == 0;
    }
  }
  for (auto& [job, phases] : open)
    for (auto& [p, since] : phases) row(job).bars.push_back({p, since, t.end_s});
  for (auto& r : t.jobs)
    std::stable_sort(r.bars.begin(), r.bars.end(),
                     [](const PhaseBar& a, const PhaseBar& b) { return a.from_s < b.from_s; });
  return t;
}

}  // namespace autonomy::courier_plot
