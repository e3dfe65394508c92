#include "gantt_svg.hpp"

#include <algorithm>
#include <sstream>

namespace autonomy::planner {

std::string gantt_svg(const FlexiblePlan& plan) {
  const double left = 160, width = 900, row = 34, top = 30;
  std::int64_t span = std::max<std::int64_t>(1, plan.makespan);
  for (const PlanToken& t : plan.tokens) span = std::max(span, std::min(t.end_ub, plan.horizon));
  auto x = [&](std::int64_t time) {
    return left + width * double(std::min(time, span)) / double(span);
  };
  std::ostringstream s;
  const double height = top + row * double(plan.timelines.size()) + 30;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << left + width + 20 << "' height='"
    << height << "' font-family='sans-serif' font-size='11'>\n";
  s << "<text x='" << left << "' y='16'>makespan " << plan.makespan << " of horizon "
    << plan.horizon << "</text>\n";
  for (std::size_t r = 0; r < plan.timelines.size(); ++r) {
    const PlanTimeline& tl = plan.timelines[r];
    const double y = top + row * double(r);
    s << "<text x='4' y='" << y + row / 2 + 4 << "'>" << tl.name << "</text>\n";
    s << "<line x1='" << left << "' y1='" << y + row - 2 << "' x2='" << left + width << "' y2='"
      << y + row - 2 << "' stroke='#ddd'/>\n";
    for (auto id : tl.tokens) {
      const PlanToken& t = plan.tokens[id];
      const double x0 = x(t.start_lb), x1 = std::max(x(t.end_lb), x0 + 1);
      s << "<rect x='" << x0 << "' y='" << y + 6 << "' width='" << x1 - x0 << "' height='"
        << row - 14 << "' fill='#8ab4e8' stroke='#235'><title>" << t.predicate << " start ["
        << t.start_lb << ", " << t.start_ub << "] end [" << t.end_lb << ", " << t.end_ub
        << "]</title></rect>\n";
      // Whiskers: how late the start and the end may still move.
      s << "<line x1='" << x0 << "' y1='" << y + 8 << "' x2='" << x(t.start_ub) << "' y2='" << y + 8
        << "' stroke='#c33'/>\n";
      s << "<line x1='" << x1 << "' y1='" << y + row - 10 << "' x2='" << x(t.end_ub) << "' y2='"
        << y + row - 10 << "' stroke='#c33'/>\n";
      s << "<text x='" << x0 + 2 << "' y='" << y + row / 2 + 3 << "'>" << t.predicate;
      if (!t.parameters.empty()) {
        s << "(";
        for (std::size_t i = 0; i < t.parameters.size(); ++i)
          s << (i ? "," : "") << t.parameters[i];
        s << ")";
      }
      s << "</text>\n";
    }
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace autonomy::planner
