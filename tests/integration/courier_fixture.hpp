#pragma once
// The courier service's integration fixture: the real simulator on the shipped office floor
// (lockstep), rhino's behavior process and the courier process over DDS, the test's observers,
// command writer and lockstep hand (it holds tick 0 until both paper commands are accepted, or
// steps the world itself). Shared by courier_test.cpp and courier_doors_test.cpp.
#include "tests/support/process_test.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace autonomy::test {


inline constexpr char kRedLetter[] =
    "put the red letter on the meeting table in room A-111 on the desk in room A-120 within 1 minute";
inline constexpr char kGreenBook[] = "deliver the green book from the librarian's desk in room A-110 to the desk in room A-114";

// A-120's door in the shipped office floor: closes at 15 s (just after the red letter is loaded),
// opens at 40 s (while the green book is fetched): the paper's Fig. 5.
inline const std::string kFig5Script =
    "  script {\n    events { time_s: 15 angle: 0.0000000 }\n    events { time_s: 40 angle: 1.5707963 }\n  }\n";
inline const std::string kFig7Script = "  script {\n    events { time_s: 15 angle: 0.0000000 }\n  }\n";

// The shipped office floor with A-120's script replaced by `a120_script` ("" = the door stays
// open), and `extra` appended.
inline std::string office_scenario(const std::string& a120_script, const std::string& extra = "") {
  std::string text = read_file(std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt");
  const auto at = text.find(kFig5Script);
  if (at != std::string::npos) text.replace(at, kFig5Script.size(), a120_script);
  return text + extra;
}

inline constexpr auto kRun = std::chrono::seconds(120);

// A courier command in restricted English from "test", once the courier reads commands.
inline void send_command_text(dds::Writer<msg::CourierCommand>& writer, const std::string& id, const std::string& text) {
  ASSERT_TRUE(writer.wait_for_readers(1, kDeadline));
  msg::CourierCommand c;
  c.command_id = id;
  c.requester = "test";
  c.text = text;
  writer.write(c);
}

class CourierTest : public ProcessTest {
 protected:
  void start_world(const std::string& scenario_text, std::vector<std::string> wait_for_too = {}) {
    scenario_ = dir().file("office.pbtxt");
    write_file(scenario_, scenario_text);
    journal_ = dir().file("courier.db");
    std::vector<std::string> args = {"--config", scenario_, "--mode", "lockstep", "--wait-for", "behavior/rhino",
                                     "--wait-for", "courier/main", "--wait-for", "test/commands", "--trajectory",
                                     dir().file("trajectory.csv")};
    for (const auto& name : wait_for_too) args.insert(args.end(), {"--wait-for", name});
    simulator_ = &start_simulator(args);
    behavior_ = &start_behavior("rhino", {"--config", scenario_});
    courier_ = &start_courier();
  }
  ChildProcess& start_courier(const std::string& name = "courier") {
    return start(name, AUTONOMY_COURIER_BIN,
                 {"--config", scenario_, "--journal", journal_, "--events", dir().file("events.jsonl"), "--domain",
                  std::to_string(domain_), "--log-dir", dir().path()});
  }
  void send(const std::string& id, const std::string& text) { send_command_text(*command_writer_, id, text); }
  // The world waits at tick 0 while the test is a lockstep participant that never acknowledges.
  void hold_world() { registration_writer_->write({"test/commands", true}); }
  // The world starts only while every --wait-for participant is registered: rhino's behavior must
  // have registered before the test leaves (it registers before it says ready).
  void release_world() {
    if (behavior_) {
      EXPECT_TRUE(await_ready(*beats_, *behavior_));
    }
    registration_writer_->write({"test/commands", false});
  }
  // While registered, the test steps the world itself: it acknowledges tick after tick until
  // `condition` holds after one, and then stops acknowledging, so the world waits right there.
  ::testing::AssertionResult step_until(const std::string& what, const std::function<bool()>& condition) {
    int64_t acked = -1;
    return await(what, [&] {
      std::optional<int64_t> latest;
      for (const auto& c : clock_->poll()) latest = std::max(latest.value_or(c.tick), c.tick);
      if (!latest || *latest <= acked) return false;
      poll();
      if (condition()) return true;
      acked = *latest;
      ack_writer_->write({"test/commands", acked, 0});
      return false;
    }, kRun);
  }
  void poll() {
    objects_->poll();
    jobs_->poll();
    replies_->poll();
    reports_->poll();
  }
  // The first tick after `after` at which `object` was seen as `where` (carried, or at a place).
  std::optional<int64_t> object_tick(const std::string& object, const std::string& carrier, const std::string& place,
                                     int64_t after = 0) {
    for (const auto& o : objects_->all())
      if (o.object_id == object && o.carrier == carrier && o.place == place && o.tick > after) return o.tick;
    return std::nullopt;
  }
  std::optional<msg::CourierJobStatus> job_in(const std::string& job, msg::JobState state) {
    for (const auto& s : jobs_->all())
      if (s.job_id == job && s.state == state) return s;
    return std::nullopt;
  }
  // rhino2, not in the scenario: attached at the east end of the hallway with the courier capability.
  ChildProcess& start_rhino2() {
    return start_behavior("rhino2", {"--config", scenario_, "--start", "38.5", "8", "3.1416", "--capability", "courier"});
  }
  // Structured deliveries of object ids (the fleet tests' three jobs).
  void deliver(const std::string& id, const std::string& object, const std::string& from, const std::string& to) {
    ASSERT_TRUE(command_writer_->wait_for_readers(1, kDeadline));
    msg::CourierCommand c;
    c.command_id = id;
    c.requester = "test";
    c.kind = msg::CourierCommandKind::Deliver;
    c.object_id = object;
    c.from = from;
    c.to = to;
    command_writer_->write(c);
  }
  // Two parcels in the east (stations at A-119 and A-117 for them, 5.5 m apart) and the blue
  // letter in the west: job-1 and job-2 east, job-3 west.
  void send_fleet_jobs() {
    ASSERT_TRUE(await_ready(*beats_, *courier_));
    deliver("e1", "parcel-e1", "a119-desk", "a112-desk");
    deliver("e2", "parcel-e2", "a117-desk", "a119-desk");
    deliver("w1", "letter-3", "meeting-table", "librarian-desk");
    ASSERT_TRUE(await("three commands answered", [&] {
      poll();
      return replies_->all().size() >= 3;
    }));
    for (const auto& r : replies_->all()) ASSERT_TRUE(r.accepted) << r.command_id << ": " << r.reason << " " << r.detail;
  }
  static std::string fleet_extra() {
    return "objects { id: \"parcel-e1\" kind: \"parcel\" colour: \"grey\" place: \"a119-desk\" }\n"
           "objects { id: \"parcel-e2\" kind: \"parcel\" colour: \"black\" place: \"a117-desk\" }\n"
           "loading_stations { place: \"a119-desk\" handover_time { fixed_s: 5 } }\n"
           "loading_stations { place: \"a117-desk\" handover_time { fixed_s: 5 } }\n";
  }
  ::testing::AssertionResult jobs_finished(const std::vector<std::string>& ids, const std::string& what) {
    auto result = await(what, [&] {
      poll();
      return std::all_of(ids.begin(), ids.end(), [&](const std::string& id) { return finished(id); });
    }, 2 * kRun);
    if (!result)
      for (const auto& id : ids) result << "\n" << id << job_story(id);
    return result;
  }
  ::testing::AssertionResult both_jobs_finished(const std::string& what) {
    auto result = await(what, [&] {
      poll();
      return finished("job-1") && finished("job-2");
    }, kRun);
    if (!result) result << "\n" << job_story("job-1") << "\n" << job_story("job-2");
    return result;
  }
  bool finished(const std::string& job) {
    return job_in(job, msg::JobState::Completed) || job_in(job, msg::JobState::Failed) ||
           job_in(job, msg::JobState::Cancelled);
  }
  std::string job_story(const std::string& job) {
    std::string out;
    for (const auto& s : jobs_->all())
      if (s.job_id == job)
        out += std::string(" -> ") + msg::to_string(s.state) + (s.phase.empty() ? "" : "/" + s.phase) +
               (s.reason.empty() ? "" : " (" + s.reason + ")") + "@" + std::to_string(s.tick);
    return out;
  }
  // The courier's events file (--events): kind and text of each line, in order.
  std::vector<std::pair<std::string, nlohmann::json>> events() {
    std::vector<std::pair<std::string, nlohmann::json>> out;
    std::istringstream in(read_file(dir().file("events.jsonl")));
    for (std::string line; std::getline(in, line);) {
      if (line.empty()) continue;
      const auto j = nlohmann::json::parse(line);
      if (j.at("kind") != "heading" && j.at("kind") != "accepted") out.emplace_back(j.at("kind"), j);
    }
    return out;
  }
  // The paper's Fig. 5 (A-120 closes after the red letter is loaded, opens while the green book
  // is fetched), as objects moved in the world and as the courier's own events, in order.
  void expect_fig5_sequence() {
    const auto red_loaded = object_tick("letter-red", "rhino", "");
    const auto opportunistic = job_in("job-1", msg::JobState::Opportunistic);
    const auto green_loaded = object_tick("book-green", "rhino", "");
    const auto red_delivered = object_tick("letter-red", "", "michael-desk");
    const auto green_delivered = object_tick("book-green", "", "a114-desk");
    ASSERT_TRUE(opportunistic) << job_story("job-1");
    ASSERT_TRUE(red_loaded && green_loaded && red_delivered && green_delivered) << job_story("job-1");
    EXPECT_NE(opportunistic->reason.find("A-120 closed at"), std::string::npos) << opportunistic->reason;
    // The paper's steps 2 to 7, in order.
    EXPECT_LT(*red_loaded, opportunistic->tick);
    EXPECT_LT(opportunistic->tick, *green_loaded);
    EXPECT_LT(*green_loaded, *red_delivered);
    EXPECT_LT(*red_delivered, *green_delivered);  // the green book's delivery was interrupted for it
    EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
    EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");

    // The courier's own account, step by step as in the paper: A-120 is seen open on the way from
    // the librarian (x = 3.5) to A-114 (x = 19), and the green book's delivery gives way.
    const std::vector<std::pair<std::string, std::string>> expected = {
        {"loaded", "letter-red"},         {"door_closed", "A-120"}, {"failed_over", "job-1"},
        {"loaded", "book-green"},         {"door_opened", "A-120"}, {"opportunity_taken", "job-1"},
        {"unloaded", "letter-red"},       {"unloaded", "book-green"}};
    const auto story = events();
    size_t next = 0;
    std::string told;
    for (const auto& [kind, line] : story) {
      const std::string text = line.at("text");
      told += kind + ": " + text + "\n";
      if (next < expected.size() && kind == expected[next].first && text.find(expected[next].second) != std::string::npos) {
        if (kind == "door_opened") {
          const double x = line.at("robots").at("rhino").at(0);
          EXPECT_GT(x, 3.5);
          EXPECT_LT(x, 19.0);
        }
        ++next;
      }
    }
    EXPECT_EQ(next, expected.size()) << "the paper's steps, in order, not all found in:\n" << told;

  }
  void setup_observers(int domain) {
    join(domain);
    beats_.emplace(participant(), dds::topics::heartbeat);
    objects_.emplace(participant(), dds::topics::truth_object);
    jobs_.emplace(participant(), dds::topics::courier_job_status);
    replies_.emplace(participant(), dds::topics::courier_reply);
    reports_.emplace(participant(), dds::topics::courier_report);
    command_topic_.emplace(participant(), dds::topics::courier_command);
    command_writer_.emplace(participant(), *command_topic_);
    clock_.emplace(participant(), dds::topics::clock);
    ack_topic_.emplace(participant(), dds::topics::tick_ack);
    ack_writer_.emplace(participant(), *ack_topic_);
    registration_topic_.emplace(participant(), dds::topics::lockstep_registration);
    registration_writer_.emplace(participant(), *registration_topic_);
    hold_world();
  }
  // Both paper commands accepted as job-1 (red letter) and job-2 (green book).
  // keep_holding: the test stays a lockstep participant (to step the world with step_until).
  void send_paper_commands(bool keep_holding = false) {
    ASSERT_TRUE(await_ready(*beats_, *courier_));
    send("c1", kRedLetter);
    send("c2", kGreenBook);
    ASSERT_TRUE(await("both commands answered", [&] {
      poll();
      return replies_->all().size() >= 2;
    }));
    for (const auto& r : replies_->all()) ASSERT_TRUE(r.accepted) << r.command_id << ": " << r.reason << " " << r.detail;
    if (!keep_holding) release_world();
  }

  std::string scenario_, journal_;
  ChildProcess* simulator_ = nullptr;
  ChildProcess* behavior_ = nullptr;
  ChildProcess* courier_ = nullptr;
  std::optional<Recorder<msg::Heartbeat>> beats_;
  std::optional<Recorder<msg::ObjectState>> objects_;
  std::optional<Recorder<msg::CourierJobStatus>> jobs_;
  std::optional<Recorder<msg::CourierReply>> replies_;
  std::optional<Recorder<msg::CourierReport>> reports_;
  std::optional<dds::Topic<msg::CourierCommand>> command_topic_;
  std::optional<dds::Writer<msg::CourierCommand>> command_writer_;
  std::optional<Recorder<msg::SimClock>> clock_;
  std::optional<dds::Topic<msg::TickAck>> ack_topic_;
  std::optional<dds::Writer<msg::TickAck>> ack_writer_;
  std::optional<dds::Topic<msg::LockstepRegistration>> registration_topic_;
  std::optional<dds::Writer<msg::LockstepRegistration>> registration_writer_;
};

}  // namespace autonomy::test
