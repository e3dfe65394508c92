#include "run_report.hpp"

#include <algorithm>
#include <map>
#include <sstream>

#include "executive.hpp"

namespace autonomy::executive {
namespace {

std::string escaped(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '&') out += "&amp;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

std::string clock_text(Time t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%02lld:%02lld:%02lld", static_cast<long long>(t / 3600),
                static_cast<long long>(t / 60 % 60), static_cast<long long>(t % 60));
  return buf;
}

bool is_fault(const std::string& kind) { return kind.rfind("fault", 0) == 0 || kind == "aborted" || kind == "watchdog"; }

}  // namespace

bool RunReport::reported(const std::string& kind) {
  return is_fault(kind) || kind == "plan_executing" || kind == "horizon_joined" || kind == "goal_lost" ||
         kind == "violation" || kind == "plan_refused" || kind == "plan_late" || kind == "settling";
}

void RunReport::add_plan(const std::string& plan_id, const Dispatcher& d, Time stopped_at) {
  const planner::FlexiblePlan& plan = d.plan();
  for (std::size_t i = 0; i < plan.tokens.size(); ++i) {
    const planner::PlanToken& t = plan.tokens[i];
    ReportToken r;
    r.plan_id = plan_id;
    r.timeline = t.timeline();
    r.text = t.predicate + "(";
    for (std::size_t k = 0; k < t.parameters.size(); ++k) r.text += (k ? ", " : "") + t.parameters[k];
    r.text += ")";
    r.goal = !goal_label(t.origin).empty();
    // Planned: the windows as the plan was received (tightened ones would show what happened).
    r.start_lb = d.origin() + t.start_lb;
    r.start_ub = d.origin() + t.start_ub;
    r.end_lb = d.origin() + t.end_lb;
    if (d.executed(i, true)) r.started = d.executed_at(i, true);
    if (d.executed(i, false)) r.ended = d.executed_at(i, false);
    else if (r.started) {  // cut short by an abort
      r.ended = stopped_at;
      r.cut_short = true;
    }
    tokens_.push_back(std::move(r));
  }
}

void RunReport::add_event(Time time, const std::string& kind, const std::string& text) {
  if (reported(kind)) events_.push_back({time, kind, text});
}

void RunReport::set_goals(std::vector<std::string> achieved, std::vector<std::string> lost) {
  achieved_ = std::move(achieved);
  lost_ = std::move(lost);
}

std::string RunReport::svg(Time horizon) const {
  std::vector<std::string> rows;
  for (const ReportToken& t : tokens_)
    if (std::find(rows.begin(), rows.end(), t.timeline) == rows.end()) rows.push_back(t.timeline);
  std::sort(rows.begin(), rows.end());
  const double left = 130, width = 1100, row_h = 38, top = 40;
  const double faults_top = top + row_h * static_cast<double>(rows.size()) + 20;
  std::vector<const ReportEvent*> marks;
  for (const ReportEvent& e : events_)
    if (is_fault(e.kind) || e.kind == "plan_executing" || e.kind == "horizon_joined") marks.push_back(&e);
  const double height = faults_top + 18 * static_cast<double>(marks.size()) + 30;
  const double span = static_cast<double>(std::max<Time>(horizon, 1));
  auto x = [&](Time t) { return left + width * static_cast<double>(std::clamp<Time>(t, 0, horizon)) / span; };

  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << left + width + 20 << "\" height=\"" << height
    << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
    << "<text x=\"" << left << "\" y=\"16\" font-size=\"13\">planned (outline: earliest start to earliest end, "
       "whisker: start window) against executed (filled; green goal, grey other, red cut short)</text>\n";
  for (Time t = 0; t <= horizon; t += std::max<Time>(horizon / 8, 1)) {
    s << "<line x1=\"" << x(t) << "\" y1=\"" << top - 6 << "\" x2=\"" << x(t) << "\" y2=\"" << faults_top - 10
      << "\" stroke=\"#ddd\"/>\n<text x=\"" << x(t) << "\" y=\"" << top - 10 << "\" text-anchor=\"middle\">"
      << clock_text(t) << "</text>\n";
  }
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double y = top + row_h * static_cast<double>(r);
    s << "<text x=\"4\" y=\"" << y + row_h / 2 + 4 << "\">" << escaped(rows[r]) << "</text>\n";
    for (const ReportToken& t : tokens_) {
      if (t.timeline != rows[r]) continue;
      // Planned, in the upper half.
      const double py = y + 3, ph = row_h / 2 - 5;
      s << "<rect x=\"" << x(t.start_lb) << "\" y=\"" << py << "\" width=\""
        << std::max(0.5, x(t.end_lb) - x(t.start_lb)) << "\" height=\"" << ph
        << "\" fill=\"none\" stroke=\"#446\" stroke-width=\"0.6\"><title>" << escaped(t.plan_id + ": " + t.text)
        << " planned " << clock_text(t.start_lb) << " - " << clock_text(t.end_lb) << "</title></rect>\n";
      if (t.start_ub > t.start_lb && t.start_ub < horizon * 4)
        s << "<line x1=\"" << x(t.start_lb) << "\" y1=\"" << py + ph / 2 << "\" x2=\"" << x(t.start_ub) << "\" y2=\""
          << py + ph / 2 << "\" stroke=\"#99a\"/>\n";
      if (!t.started) continue;
      // Executed, in the lower half.
      const std::string fill = t.cut_short ? "#c33" : t.goal ? "#3a3" : "#aaa";
      const double ey = y + row_h / 2, eh = row_h / 2 - 4;
      const Time end = t.ended.value_or(*t.started);
      s << "<rect x=\"" << x(*t.started) << "\" y=\"" << ey << "\" width=\"" << std::max(0.8, x(end) - x(*t.started))
        << "\" height=\"" << eh << "\" fill=\"" << fill << "\" fill-opacity=\"0.8\"><title>" << escaped(t.text)
        << " executed " << clock_text(*t.started) << " - " << clock_text(end) << "</title></rect>\n";
    }
  }
  s << "<text x=\"4\" y=\"" << faults_top << "\" font-size=\"12\">faults and responses</text>\n";
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const ReportEvent& e = *marks[i];
    const std::string colour = is_fault(e.kind) ? "#c22" : "#26c";
    const double y = faults_top + 18 * static_cast<double>(i + 1);
    s << "<line x1=\"" << x(e.time) << "\" y1=\"" << top << "\" x2=\"" << x(e.time) << "\" y2=\"" << y - 4
      << "\" stroke=\"" << colour << "\" stroke-dasharray=\"3,2\" stroke-width=\"0.8\"/>\n"
      << "<text x=\"" << x(e.time) + 3 << "\" y=\"" << y << "\" fill=\"" << colour << "\">" << clock_text(e.time) << " "
      << escaped(e.kind + ": " + e.text.substr(0, 110)) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

std::string RunReport::markdown(const std::string& title, Time horizon) const {
  std::ostringstream s;
  s << "# " << title << "\n\n![planned against executed](plan.svg)\n\n";
  s << "Mission time 00:00:00 to " << clock_text(horizon) << "; " << achieved_.size() << " goals achieved, "
    << lost_.size() << " lost.\n\n## Faults and responses\n\n| time | what | detail |\n|---|---|---|\n";
  for (const ReportEvent& e : events_)
    if (e.kind != "goal_lost") s << "| " << clock_text(e.time) << " | " << e.kind << " | " << e.text << " |\n";
  s << "\n## Goals achieved\n\n";
  for (const std::string& g : achieved_) s << "- " << g << "\n";
  s << "\n## Goals lost\n\n";
  if (lost_.empty()) s << "none\n";
  for (const std::string& g : lost_) s << "- " << g << "\n";
  std::map<std::string, std::size_t> per_plan;
  for (const ReportToken& t : tokens_) ++per_plan[t.plan_id];
  s << "\n## Plans\n\n| plan | tokens |\n|---|---|\n";
  for (const auto& [id, n] : per_plan) s << "| " << id << " | " << n << " |\n";
  return s.str();
}

}  // namespace autonomy::executive
