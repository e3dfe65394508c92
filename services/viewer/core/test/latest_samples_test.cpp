// LatestSamples: the latest bytes of each instance walked once per flush, ended instances out
// of the panels, bytes that do not fit reported without losing the panel.
#include "services/viewer/core/latest_samples.hpp"

#include <gtest/gtest.h>

#include "tools/xtypes/cdr_encode.hpp"

namespace autonomy::viewer {
namespace {

using xtypes::Kind;

// struct Telemetry { @key string craft; int64 tick; double battery; }, as a type tree.
xtypes::TypePtr telemetry_type() {
  auto t = xtypes::make_type(Kind::Struct);
  t->name = "test::Telemetry";
  t->members.push_back({"craft", 0, xtypes::make_type(Kind::String), true});
  t->members.push_back({"tick", 1, xtypes::make_type(Kind::Int64)});
  t->members.push_back({"battery", 2, xtypes::make_type(Kind::Float64)});
  return t;
}

std::string sample(const xtypes::Type& type, const std::string& craft, int64_t tick, double battery) {
  return xtypes::json_to_cdr(type, {{"craft", craft}, {"tick", tick}, {"battery", battery}}).cdr;
}

TEST(LatestSamplesTest, WalksOnlyTheLatestSampleOfEachInstancePerFlush) {
  const auto type = telemetry_type();
  LatestSamples latest(type, "spacecraft");
  Panels panels;
  for (int64_t tick = 1; tick <= 1000; ++tick) latest.add(7, true, sample(*type, "ds1", tick, 0.5));
  latest.add(8, true, sample(*type, "ds2", 3, 0.25));
  EXPECT_EQ(latest.walked(), 0u);  // nothing walked as samples arrive
  EXPECT_TRUE(latest.flush(panels).empty());
  EXPECT_EQ(latest.walked(), 2u);  // one per instance, not 1,001
  auto f = panels.frame();
  EXPECT_EQ(f["spacecraft"]["ds1"]["tick"], 1000);
  EXPECT_EQ(f["spacecraft"]["ds2"]["battery"], 0.25);

  // Nothing new: nothing walked, the panels unchanged.
  const uint64_t version = panels.version();
  EXPECT_TRUE(latest.flush(panels).empty());
  EXPECT_EQ(latest.walked(), 2u);
  EXPECT_EQ(panels.version(), version);

  latest.add(7, true, sample(*type, "ds1", 1001, 0.4));
  latest.flush(panels);
  EXPECT_EQ(latest.walked(), 3u);
  EXPECT_EQ(panels.frame()["spacecraft"]["ds1"]["tick"], 1001);
}

TEST(LatestSamplesTest, AnEndedInstanceLeavesThePanelsAndOneNeverShownLeavesNothing) {
  const auto type = telemetry_type();
  LatestSamples latest(type, "spacecraft");
  Panels panels;
  latest.add(7, true, sample(*type, "ds1", 1, 0.5));
  latest.flush(panels);
  latest.add(7, true, sample(*type, "ds1", 2, 0.5));
  latest.add(7, false, {});  // disposed after a sample not yet shown
  latest.add(9, true, sample(*type, "ds3", 1, 0.5));
  latest.add(9, false, {});  // came and went between two flushes
  latest.flush(panels);
  EXPECT_TRUE(panels.frame()["spacecraft"].empty());
  EXPECT_EQ(latest.walked(), 1u);

  // The same instance handle alive again is shown again.
  latest.add(7, true, sample(*type, "ds1", 5, 0.5));
  latest.flush(panels);
  EXPECT_EQ(panels.frame()["spacecraft"]["ds1"]["tick"], 5);
}

TEST(LatestSamplesTest, BytesThatDoNotFitAreReportedAndThePanelKeepsItsLastSample) {
  const auto type = telemetry_type();
  LatestSamples latest(type, "spacecraft");
  Panels panels;
  latest.add(7, true, sample(*type, "ds1", 1, 0.5));
  latest.flush(panels);
  std::string cut = sample(*type, "ds1", 2, 0.5);
  cut.resize(cut.size() - 6);
  latest.add(7, true, cut);
  const auto errors = latest.flush(panels);
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_FALSE(errors[0].empty());
  EXPECT_EQ(panels.frame()["spacecraft"]["ds1"]["tick"], 1);
}

TEST(LatestSamplesTest, PanelKeysJoinTheKeyValues) {
  EXPECT_EQ(panel_key({{"craft", "ds1"}}), "ds1");
  EXPECT_EQ(panel_key({{"robot", "r1"}, {"id", 3}}), "r1/3");
  EXPECT_EQ(panel_key(nlohmann::ordered_json::object()), "");
}

}  // namespace
}  // namespace autonomy::viewer
