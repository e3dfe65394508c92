#pragma once
// The paper's office at 09:30 (simulated time 3600 s after the 08:30 start), for the language
// tests, and short ways to ask it something.
#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/knowledge/test/paper_office.hpp"
#include "services/courier/core/language/command_interpreter.hpp"

#include <gtest/gtest.h>

#include <string>

namespace autonomy::courier::test {

inline constexpr double kNowSim = 3600.0;  // 09:30

inline Interpretation accepted_delivery(const std::string& text, const OfficeKnowledge& k) {
  const CommandAnswer a = interpret_command(text, k, kNowSim);
  EXPECT_EQ(a.kind, CommandAnswer::Kind::delivery) << text << "\n  " << a.summary();
  return a.delivery;
}

inline Rejection rejected(const std::string& text, const OfficeKnowledge& k) {
  const CommandAnswer a = interpret_command(text, k, kNowSim);
  EXPECT_EQ(a.kind, CommandAnswer::Kind::rejected) << text << "\n  " << a.summary();
  return a.rejection;
}

}  // namespace autonomy::courier::test
