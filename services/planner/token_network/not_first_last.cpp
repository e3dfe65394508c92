#include "not_first_last.hpp"

#include <algorithm>
#include <limits>

namespace autonomy::planner {

std::vector<UnaryWindow> not_first_not_last(const std::vector<UnaryWindow>& w) {
  const std::size_t n = w.size();
  std::vector<UnaryWindow> out = w;
  std::vector<char> inside(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b) {
      if (w[a].est >= w[b].lct) continue;
      // Omega = the tokens within [est(a), lct(b)], with what the rules need of it.
      Time p = 0, est = std::numeric_limits<Time>::max(), lct = std::numeric_limits<Time>::min();
      Time max_lst = std::numeric_limits<Time>::min(), min_ect = std::numeric_limits<Time>::max();
      std::size_t size = 0;
      for (std::size_t j = 0; j < n; ++j) {
        inside[j] = w[j].est >= w[a].est && w[j].lct <= w[b].lct;
        if (!inside[j]) continue;
        ++size;
        p += w[j].duration;
        est = std::min(est, w[j].est);
        lct = std::max(lct, w[j].lct);
        max_lst = std::max(max_lst, w[j].lct - w[j].duration);
        min_ect = std::min(min_ect, w[j].est + w[j].duration);
      }
      if (size == 0) continue;
      for (std::size_t i = 0; i < n; ++i) {
        if (inside[i]) continue;
        if (est + p > w[i].lct - w[i].duration) out[i].lct = std::min(out[i].lct, max_lst);
        if (w[i].est + w[i].duration > lct - p) out[i].est = std::max(out[i].est, min_ect);
      }
    }
  }
  return out;
}

}  // namespace autonomy::planner
