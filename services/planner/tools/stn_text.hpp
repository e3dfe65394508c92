#pragma once
// The temporal network driven alone from text: "horizon H", "timepoint NAME ...", and
// constraint lines "FROM TO LB UB" (LB <= TO - FROM <= UB; "origin" is time 0, "inf" no bound).
// The answer: every timepoint's [earliest, latest], or the line whose constraint closes a
// negative cycle together with the lines of the rest of the cycle.
#include <string>
#include <string_view>

namespace autonomy::planner {

struct StnReport {
  bool ok = true;  // the text was well formed (else `text` is the error, file:line: ...)
  bool consistent = true;
  std::string text;  // bounds, one "name earliest latest" a line, or the conflict
};

StnReport run_stn_text(std::string_view text, const std::string& file);

}  // namespace autonomy::planner
