#include "stn_text.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <vector>

#include "temporal_network.hpp"

namespace autonomy::planner {

StnReport run_stn_text(std::string_view text, const std::string& file) {
  StnReport report;
  std::istringstream in{std::string(text)};
  std::string line;
  unsigned number = 0;
  Time horizon = kInfinity;
  std::map<std::string, TimepointId> names{{"origin", TemporalNetwork::origin()}};
  std::vector<std::string> order{"origin"};
  struct Line {
    unsigned number;
    TimepointId from, to;
    Time lb, ub;
  };
  std::vector<Line> constraints;
  auto fail = [&](const std::string& why) {
    report.ok = false;
    report.text = file + ":" + std::to_string(number) + ": " + why;
    return report;
  };
  auto time_of = [](const std::string& word, Time* out) {
    if (word == "inf" || word == "+inf") return *out = kInfinity, true;
    if (word == "-inf") return *out = -kInfinity, true;
    try {
      std::size_t used = 0;
      long long v = std::stoll(word, &used);
      if (used != word.size() || std::llabs(v) >= kInfinity) return false;
      *out = v;
      return true;
    } catch (const std::exception&) {
      return false;
    }
  };
  while (std::getline(in, line)) {
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string x; words >> x;) w.push_back(x);
    if (w.empty()) continue;
    if (w[0] == "horizon") {
      if (w.size() != 2 || !time_of(w[1], &horizon) || horizon <= 0)
        return fail("expected 'horizon N' with a positive integer N");
      if (names.size() > 1 || !constraints.empty()) return fail("the horizon comes first");
    } else if (w[0] == "timepoint") {
      if (w.size() < 2) return fail("expected 'timepoint NAME ...'");
      for (std::size_t i = 1; i < w.size(); ++i) {
        if (!names.emplace(w[i], names.size()).second)
          return fail("timepoint '" + w[i] + "' declared twice");
        order.push_back(w[i]);
      }
    } else {
      if (w.size() != 4) return fail("expected 'FROM TO LB UB'");
      auto from = names.find(w[0]), to = names.find(w[1]);
      if (from == names.end()) return fail("unknown timepoint '" + w[0] + "'");
      if (to == names.end()) return fail("unknown timepoint '" + w[1] + "'");
      Line c{number, from->second, to->second, 0, 0};
      if (!time_of(w[2], &c.lb) || !time_of(w[3], &c.ub))
        return fail("bounds must be integers or inf");
      if (c.lb > c.ub) return fail("lb " + w[2] + " > ub " + w[3]);
      constraints.push_back(c);
    }
  }
  TemporalNetwork tn(horizon);
  tn.set_explain_conflicts(true);
  for (std::size_t i = 1; i < order.size(); ++i) tn.add_timepoint();
  std::vector<unsigned> line_of;  // per constraint id
  for (const Line& c : constraints) {
    TemporalResult r = tn.add_constraint(c.from, c.to, c.lb, c.ub);
    line_of.push_back(c.number);
    if (!r) {
      report.consistent = false;
      std::ostringstream out;
      out << file << ":" << c.number << ": closes a negative cycle with";
      for (TemporalConstraintId id : r.conflict) {
        if (id == TemporalNetwork::kHorizonConstraint)
          out << " the horizon";
        else if (id < line_of.size() && line_of[id] != c.number)
          out << " line " << line_of[id];
      }
      report.text = out.str();
      return report;
    }
  }
  std::ostringstream out;
  for (std::size_t i = 1; i < order.size(); ++i) {
    out << order[i] << ' ' << tn.earliest(i) << ' ';
    if (tn.latest(i) >= kInfinity)
      out << "inf";
    else
      out << tn.latest(i);
    out << '\n';
  }
  report.text = out.str();
  return report;
}

}  // namespace autonomy::planner
