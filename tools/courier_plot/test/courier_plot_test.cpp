#include "tools/courier_plot/courier_svg.hpp"

#include <gtest/gtest.h>

namespace autonomy::courier_plot {
namespace {

// Fig. 5 in small: red letter loaded, A-120 closed (failure in the same tick), green book
// loaded, A-120 open (opportunity in the same tick), red letter delivered, green book delivered.
const char* kEvents =
    R"ev({"kind":"accepted","sim_s":0.0,"text":"job job-1 accepted","tick":0,"time":"09:00:00"}
{"kind":"accepted","sim_s":0.0,"text":"job job-2 accepted","tick":0,"time":"09:00:00"}
{"kind":"heading","robots":{"rhino":[1.5,8.0]},"sim_s":0.1,"text":"rhino heads for meeting-table (09:00:00)","tick":1,"time":"09:00:00"}
{"kind":"loaded","robots":{"rhino":[3.7,10.5]},"sim_s":11.0,"text":"letter-red loaded at meeting-table by rhino at 09:00:11","tick":110,"time":"09:00:11"}
{"kind":"door_closed","robots":{"rhino":[8.9,7.5]},"sim_s":27.0,"text":"A-120 seen closed by rhino at 09:00:27","tick":270,"time":"09:00:27"}
{"kind":"failed_over","robots":{"rhino":[8.9,7.5]},"sim_s":27.0,"text":"job job-1 failed over to opportunistic: A-120 closed at 09:00:27 (09:00:27)","tick":270,"time":"09:00:27"}
{"kind":"loaded","robots":{"rhino":[3.3,4.7]},"sim_s":58.0,"text":"book-green loaded at librarian-desk by rhino at 09:00:58","tick":580,"time":"09:00:58"}
{"kind":"door_opened","robots":{"rhino":[8.9,7.5]},"sim_s":73.0,"text":"A-120 seen open by rhino at 09:01:13","tick":730,"time":"09:01:13"}
{"kind":"opportunity_taken","robots":{"rhino":[8.9,7.5]},"sim_s":73.0,"text":"opportunity: job job-1 taken up now (09:01:13)","tick":730,"time":"09:01:13"}
{"kind":"unloaded","robots":{"rhino":[13.0,2.9]},"sim_s":92.0,"text":"letter-red unloaded at michael-desk by rhino at 09:01:32","tick":920,"time":"09:01:32"}
{"kind":"finished","robots":{"rhino":[13.0,2.9]},"sim_s":92.0,"text":"job job-1 delivered the red letter (letter-red) to michael-desk at 09:01:32","tick":920,"time":"09:01:32"}
{"kind":"unloaded","robots":{"rhino":[19.0,2.9]},"sim_s":123.0,"text":"book-green unloaded at a114-desk by rhino at 09:02:03","tick":1230,"time":"09:02:03"}
{"kind":"finished","robots":{"rhino":[19.0,2.9]},"sim_s":123.0,"text":"job job-2 delivered the green book (book-green) to a114-desk at 09:02:03","tick":1230,"time":"09:02:03"}
)ev";

std::vector<CourierEvent> events() {
  auto parsed = parse_events(kEvents, "fig5.jsonl");
  EXPECT_FALSE(parsed.error) << *parsed.error;
  return parsed.events;
}

TEST(CourierSteps, NumberedAsInThePapersFigure) {
  const auto steps = numbered_steps(events(), geometry::Vec2(1.5, 8.0), "rhino");
  ASSERT_EQ(steps.size(), 7u);  // the paper's steps 1..7
  const std::vector<std::vector<std::string>> kinds{{"start"},
                                                    {"loaded"},
                                                    {"door_closed", "failed_over"},
                                                    {"loaded"},
                                                    {"door_opened", "opportunity_taken"},
                                                    {"unloaded"},
                                                    {"unloaded"}};
  for (size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].number, static_cast<int>(i) + 1);
    ASSERT_EQ(steps[i].lines.size(), kinds[i].size()) << "step " << i + 1;
    for (size_t k = 0; k < kinds[i].size(); ++k) EXPECT_EQ(steps[i].lines[k].kind, kinds[i][k]);
  }
  EXPECT_EQ(steps[2].lines[0].text, "A-120 seen closed by rhino");
  EXPECT_EQ(steps[2].lines[0].time, "09:00:27");
  EXPECT_DOUBLE_EQ(steps[2].position.x(), 8.9);
}

TEST(CourierTimeline, BarsPerJobFromTheEventsInOrder) {
  const Timeline t = job_timeline(events());
  ASSERT_EQ(t.jobs.size(), 2u);
  const JobRow& red = t.jobs[0];
  EXPECT_EQ(red.id, "job-1");
  EXPECT_EQ(red.object, "letter-red");
  ASSERT_EQ(red.bars.size(), 3u);
  EXPECT_EQ(red.bars[0].phase, Phase::Waiting);
  EXPECT_DOUBLE_EQ(red.bars[0].from_s, 0.0);
  EXPECT_DOUBLE_EQ(red.bars[0].to_s, 11.0);
  EXPECT_EQ(red.bars[1].phase, Phase::Carried);
  EXPECT_DOUBLE_EQ(red.bars[1].from_s, 11.0);
  EXPECT_DOUBLE_EQ(red.bars[1].to_s, 92.0);
  EXPECT_EQ(red.bars[2].phase, Phase::Opportunistic);
  EXPECT_DOUBLE_EQ(red.bars[2].from_s, 27.0);
  EXPECT_DOUBLE_EQ(red.bars[2].to_s, 73.0);
  EXPECT_FALSE(red.failed);
  EXPECT_EQ(red.outcome, "delivered the red letter (letter-red) to michael-desk");

  const JobRow& green = t.jobs[1];
  EXPECT_EQ(green.object, "book-green");
  ASSERT_EQ(green.bars.size(), 2u);
  EXPECT_DOUBLE_EQ(green.bars[0].to_s, 58.0);
  EXPECT_DOUBLE_EQ(green.bars[1].from_s, 58.0);
  EXPECT_DOUBLE_EQ(green.bars[1].to_s, 123.0);

  ASSERT_EQ(t.doors.size(), 2u);
  EXPECT_EQ(t.doors[0].door, "A-120");
  EXPECT_FALSE(t.doors[0].open);
  EXPECT_TRUE(t.doors[1].open);
}

TEST(CourierTimeline, ReturnedObjectEndsInAReturningBarAndFails) {
  auto parsed = parse_events(
      R"ev({"kind":"accepted","sim_s":0,"text":"job job-1 accepted","tick":0,"time":"09:00:00"}
{"kind":"loaded","sim_s":10,"text":"letter-red loaded at meeting-table by rhino","tick":100,"time":"09:00:10"}
{"kind":"failed_over","sim_s":20,"text":"job job-1 failed over to opportunistic: A-120 closed","tick":200,"time":"09:00:20"}
{"kind":"returning","sim_s":50,"text":"job job-1: A-120 closed; returning letter-red to meeting-table","tick":500,"time":"09:00:50"}
{"kind":"unloaded","sim_s":80,"text":"letter-red unloaded at meeting-table by rhino","tick":800,"time":"09:01:20"}
{"kind":"finished","sim_s":80,"text":"job job-1 failed: A-120 closed; letter-red returned","tick":800,"time":"09:01:20"}
)ev",
      "fig7.jsonl");
  ASSERT_FALSE(parsed.error) << *parsed.error;
  const Timeline t = job_timeline(parsed.events);
  ASSERT_EQ(t.jobs.size(), 1u);
  const auto& bars = t.jobs[0].bars;
  ASSERT_EQ(bars.size(), 4u);
  EXPECT_EQ(bars[2].phase, Phase::Opportunistic);
  EXPECT_DOUBLE_EQ(bars[2].to_s, 50.0);
  EXPECT_EQ(bars[1].phase, Phase::Carried);
  EXPECT_DOUBLE_EQ(bars[1].to_s, 50.0);
  EXPECT_EQ(bars[3].phase, Phase::Returning);
  EXPECT_DOUBLE_EQ(bars[3].from_s, 50.0);
  EXPECT_DOUBLE_EQ(bars[3].to_s, 80.0);
  EXPECT_TRUE(t.jobs[0].failed);
}

TEST(CourierSvg, PicturesCarryTheLabels) {
  sim::WorldSpec world;
  world.width = 20;
  world.height = 12;
  sim::RunPicture picture;
  picture.world = &world;
  picture.paths["rhino"] = {{1.5, 8.0}, {3.7, 10.5}, {19.0, 2.9}};
  const std::string trajectory =
      trajectory_svg(picture, numbered_steps(events(), geometry::Vec2(1.5, 8.0), "rhino"));
  EXPECT_NE(trajectory.find(">A-120 seen closed by rhino</text>"), std::string::npos);
  EXPECT_NE(trajectory.find(">opportunity: job job-1 taken up now</text>"), std::string::npos);
  EXPECT_NE(trajectory.find("font-weight=\"bold\" text-anchor=\"middle\">7</text>"),
            std::string::npos);
  EXPECT_EQ(trajectory.find(">8</text>"), std::string::npos);

  const std::string gantt = gantt_svg(job_timeline(events()), "Fig. 5");
  for (const char* label :
       {">job-1</text>", ">job-2</text>", ">09:00:30</text>", "A-120 closed 09:00:27",
        "A-120 open 09:01:13", "delivered the green book (book-green) to a114-desk"})
    EXPECT_NE(gantt.find(label), std::string::npos) << label;
}

TEST(CourierRecords, BadLinesNameFileAndLine) {
  auto bad_json = parse_events(
      "{\"kind\":\"accepted\",\"text\":\"x\",\"tick\":0,\"sim_s\":0,\"time\":\"09:00:00\"}\n{"
      "oops\n",
      "e.jsonl");
  ASSERT_TRUE(bad_json.error);
  EXPECT_EQ(*bad_json.error, "e.jsonl:2: not valid JSON");
  auto missing = parse_events(
      "{\"kind\":\"accepted\",\"tick\":0,\"sim_s\":0,\"time\":\"09:00:00\"}\n", "e.jsonl");
  ASSERT_TRUE(missing.error);
  EXPECT_EQ(*missing.error, "e.jsonl:1: 'text' missing or not a string");
  auto bad_time = parse_events(
      "{\"kind\":\"a\",\"text\":\"x\",\"tick\":0,\"sim_s\":0,\"time\":\"9h\"}\n", "e.jsonl");
  ASSERT_TRUE(bad_time.error);
  EXPECT_EQ(*bad_time.error, "e.jsonl:1: 'time' is not HH:MM:SS: '9h'");
  auto bad_csv = parse_trajectory_csv(
      "tick,time_s,robot,x,y,theta\n0,0,rhino,1,2,0\n1,0.1,rhino,x1,2,0\n", "t.csv");
  ASSERT_TRUE(bad_csv.error);
  EXPECT_EQ(*bad_csv.error, "t.csv:3: x is not a number: 'x1'");
  // The last row cut short (no newline) by a stopped simulator is ignored.
  auto good_csv = parse_trajectory_csv(
      "tick,time_s,robot,x,y,theta\n0,0,rhino,1,2,0\n1,0.1,rhino,1.5,2,0\n2,0.2,rhi", "t.csv");
  ASSERT_FALSE(good_csv.error);
  ASSERT_EQ(good_csv.paths.at("rhino").size(), 2u);
}

}  // namespace
}  // namespace autonomy::courier_plot
