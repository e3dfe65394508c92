// The courier service end to end: the real simulator on the office floor (lockstep), rhino's
// behavior process and the courier process over DDS. The paper's two commands of section 2 with
// door A-120 staying open (Fig. 6), closing after the red letter is loaded and reopening while
// the robot fetches the green book (Fig. 5), or closing for good (Fig. 7); two red letters; and a
// courier killed with SIGKILL mid-delivery that restarts from its journal.
//
// The world holds tick 0 until the test's own lockstep registration ("test/commands") arrives,
// and the test leaves lockstep only once both commands are accepted: every run starts with the
// jobs known at simulated time 0, so A-120's scripted times fall where the paper has them.
//
// The fleet: a second courier, rhino2, attached at run time by starting its behavior with
// --capability courier (it is not in the scenario); one joining while jobs run, one killed with
// SIGKILL right after it loaded a parcel.
//
// One DDS domain per test (ctest runs them in parallel); this file uses 160-169 and 190-195 only:
//
//   domain  test
//   ------  -----------------------------------------------
//    160    CourierTest.Fig6DoorStaysOpenBothDelivered
//    161    CourierTest.Fig5DoorClosesThenReopensTheRedLetterIsDeliveredOpportunistically
//    162    CourierTest.Fig7DoorStaysClosedTheRedLetterFailsAndIsReturned
//    163    CourierTest.TwoRedLettersAreNeverAboardTogether
//    164    CourierTest.KilledMidDeliveryTheRestartedCourierFinishesFromItsJournal
//    165    CourierTest.BadCommandsAreRejectedWithReasonsAndTheServiceGoesOn
//    166    CourierTest.TheCliSendsListsAndCancels
//    167    CourierTest.WhatWasLearnedIsKeptInTheJournalAcrossRunsAndPrinted
//    190    CourierTest.ARobotAttachedWhileJobsRunGetsWork
//    191    CourierTest.ARobotKilledMidDeliveryHasItsJobsReallocatedAndItsParcelReportedStranded
#include "tests/integration/courier_fixture.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <csignal>
#include <set>
#include <sstream>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;

TEST_F(CourierTest, Fig6DoorStaysOpenBothDelivered) {
  setup_observers(160);
  start_world(office_scenario(""));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
  EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");
  EXPECT_FALSE(job_in("job-1", msg::JobState::Opportunistic)) << job_story("job-1");
  const auto red_loaded = object_tick("letter-red", "rhino", "");
  const auto red_delivered = object_tick("letter-red", "", "michael-desk");
  const auto green_delivered = object_tick("book-green", "", "a114-desk");
  ASSERT_TRUE(red_loaded && red_delivered && green_delivered);
  EXPECT_LT(*red_loaded, *red_delivered);
  EXPECT_LT(*red_delivered, *green_delivered);  // A-120 lies on the way to A-114
  // A report follows its job's final status; it may still be on its way.
  ASSERT_TRUE(await("both reports", [&] {
    poll();
    return reports_->all().size() >= 2;
  }));
  for (const auto& r : reports_->all()) EXPECT_TRUE(r.success) << r.text;
}

TEST_F(CourierTest, Fig5DoorClosesThenReopensTheRedLetterIsDeliveredOpportunistically) {
  setup_observers(161);
  start_world(office_scenario(kFig5Script));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));

  expect_fig5_sequence();
}

// The letter waits aboard (the robot beside A-120's door) until the policy gives its deadline up,
// 15 minutes after it passed; then it goes back.
TEST_F(CourierTest, Fig7DoorStaysClosedTheRedLetterFailsAndIsReturned) {
  setup_observers(162);
  start_world(office_scenario(kFig7Script));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  const auto failed = job_in("job-1", msg::JobState::Failed);
  ASSERT_TRUE(failed) << job_story("job-1");
  EXPECT_NE(failed->reason.find("A-120 closed at"), std::string::npos) << failed->reason;
  EXPECT_NE(failed->reason.find("gave up waiting for A-120: deadline"), std::string::npos) << failed->reason;
  EXPECT_NE(failed->reason.find("letter-red returned to meeting-table"), std::string::npos) << failed->reason;
  EXPECT_TRUE(job_in("job-1", msg::JobState::Opportunistic)) << job_story("job-1");
  EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");
  // Not dropped: back where it came from, after the green book's delivery.
  const auto loaded = object_tick("letter-red", "rhino", "");
  ASSERT_TRUE(loaded);
  const auto returned = object_tick("letter-red", "", "meeting-table", *loaded);
  const auto green_delivered = object_tick("book-green", "", "a114-desk");
  ASSERT_TRUE(returned && green_delivered);
  EXPECT_LT(*green_delivered, *returned);
  EXPECT_FALSE(object_tick("letter-red", "", "michael-desk"));
  // The report follows the job's final status; it may still be on its way.
  const auto job_1_report = [&]() -> const msg::CourierReport* {
    for (const auto& r : reports_->all())
      if (r.job_id == "job-1") return &r;
    return nullptr;
  };
  ASSERT_TRUE(await("job-1's report", [&] {
    poll();
    return job_1_report() != nullptr;
  }));
  EXPECT_FALSE(job_1_report()->success);
  EXPECT_NE(job_1_report()->text.find("A-120 closed"), std::string::npos) << job_1_report()->text;
}

TEST_F(CourierTest, TwoRedLettersAreNeverAboardTogether) {
  setup_observers(163);
  start_world(office_scenario("", "objects { id: \"letter-red-2\" kind: \"letter\" colour: \"red\" place: \"librarian-desk\" }\n"));
  ASSERT_TRUE(await_ready(*beats_, *courier_));
  ASSERT_TRUE(command_writer_->wait_for_readers(1, kDeadline));
  msg::CourierCommand a;
  a.command_id = "a";
  a.kind = msg::CourierCommandKind::Deliver;
  a.object_id = "letter-red";
  a.from = "meeting-table";
  a.to = "Anna";
  command_writer_->write(a);
  msg::CourierCommand b = a;
  b.command_id = "b";
  b.object_id = "letter-red-2";
  b.from = "librarian";
  b.to = "Michael";
  command_writer_->write(b);
  ASSERT_TRUE(await("both commands answered", [&] {
    poll();
    return replies_->all().size() >= 2;
  }));
  release_world();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
  EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");
  // One letter's delivery ends before the other's load.
  const auto load1 = object_tick("letter-red", "rhino", "");
  const auto drop1 = object_tick("letter-red", "", "a114-desk");
  const auto load2 = object_tick("letter-red-2", "rhino", "");
  const auto drop2 = object_tick("letter-red-2", "", "michael-desk");
  ASSERT_TRUE(load1 && drop1 && load2 && drop2);
  EXPECT_TRUE(*drop1 < *load2 || *drop2 < *load1)
      << "letter-red aboard " << *load1 << ".." << *drop1 << ", letter-red-2 " << *load2 << ".." << *drop2;
}

TEST_F(CourierTest, KilledMidDeliveryTheRestartedCourierFinishesFromItsJournal) {
  setup_observers(164);
  Recorder<msg::HandoverRequest> requests(participant(), dds::topics::handover_request);
  start_world(office_scenario(""));
  send_paper_commands(true);
  ASSERT_TRUE(step_until("the red letter aboard", [&] { return object_tick("letter-red", "rhino", "").has_value(); }));
  // Mid-delivery: the letter is aboard, nothing has been delivered yet.
  EXPECT_FALSE(finished("job-1")) << job_story("job-1");
  EXPECT_FALSE(object_tick("letter-red", "", "michael-desk"));
  stop_watching(*courier_);
  courier_->signal(SIGKILL);
  ASSERT_TRUE(courier_->wait_for_exit(10s));
  release_world();
  ChildProcess& again = start_courier("courier-restarted");
  ASSERT_TRUE(await_ready(*beats_, again));
  ASSERT_TRUE(both_jobs_finished("both jobs finished after the restart"));
  EXPECT_TRUE(job_in("job-1", msg::JobState::Completed)) << job_story("job-1");
  EXPECT_TRUE(job_in("job-2", msg::JobState::Completed)) << job_story("job-2");
  EXPECT_TRUE(object_tick("letter-red", "", "michael-desk"));
  EXPECT_TRUE(object_tick("book-green", "", "a114-desk"));
  // Loaded once: the restarted courier knew the letter was aboard and asked for no second load of
  // it (a repeat of the first request's id would be answered, not served again).
  int loads = 0;
  for (const auto& o : objects_->all()) loads += o.object_id == "letter-red" && o.carrier == "rhino";
  EXPECT_EQ(loads, 1);
  requests.poll();
  std::set<std::string> load_ids;
  for (const auto& r : requests.all())
    if (r.object_id == "letter-red" && r.kind == msg::HandoverKind::Load) load_ids.insert(r.request_id);
  EXPECT_EQ(load_ids.size(), 1u);
}

TEST_F(CourierTest, BadCommandsAreRejectedWithReasonsAndTheServiceGoesOn) {
  setup_observers(165);
  start_world(office_scenario(""));
  release_world();
  ASSERT_TRUE(await_ready(*beats_, *courier_));
  send("x1", "deliver the green book from the librarian to room A-122");
  send("x2", std::string(5000, 'z'));
  msg::CourierCommand huge_id;
  huge_id.command_id = std::string(100000, 'q');
  huge_id.text = kGreenBook;
  command_writer_->write(huge_id);
  send("x3", kGreenBook);
  ASSERT_TRUE(await("four replies", [&] {
    poll();
    return replies_->all().size() >= 4;
  }));
  std::map<std::string, msg::CourierReply> by_id;
  for (const auto& r : replies_->all()) by_id[r.command_id] = r;
  EXPECT_EQ(by_id["x1"].reason, "unknown_room");
  EXPECT_EQ(by_id["x1"].word, "A-122");
  EXPECT_EQ(by_id["x2"].reason, "too_long");
  ASSERT_EQ(by_id.count(std::string(128, 'q')), 1u);
  EXPECT_EQ(by_id[std::string(128, 'q')].reason, "too_long");
  EXPECT_TRUE(by_id["x3"].accepted) << by_id["x3"].reason;
  EXPECT_TRUE(courier_->running());
}

TEST_F(CourierTest, TheCliSendsListsAndCancels) {
  setup_observers(166);
  start_world(office_scenario(""));
  ASSERT_TRUE(await_ready(*beats_, *courier_));
  const auto cli = [&](const std::string& name, std::vector<std::string> args) {
    args.insert(args.end(), {"--domain", std::to_string(domain_)});
    ChildProcess& p = start(name, AUTONOMY_AUTONOMY_BIN, args, false);
    const auto status = p.wait_for_exit(30s);
    EXPECT_TRUE(status) << name << " did not end";
    return std::make_pair(status ? (status->exited ? status->code : 128 + status->signal) : -1, read_file(p.log_file()));
  };
  const auto [sent, sent_out] = cli("send", {"courier", "send", kGreenBook});
  EXPECT_EQ(sent, 0) << sent_out;
  EXPECT_NE(sent_out.find("accepted as job-1: deliver the green book (book-green) from librarian-desk to a114-desk"),
            std::string::npos)
      << sent_out;
  const auto [bad, bad_out] = cli("send-bad", {"courier", "send", "deliver the green book to room A-122"});
  EXPECT_EQ(bad, 1) << bad_out;
  EXPECT_NE(bad_out.find("rejected (unknown_room)"), std::string::npos) << bad_out;
  EXPECT_NE(bad_out.find("^"), std::string::npos) << bad_out;  // under the word at fault
  const auto [cancelled, cancel_out] = cli("cancel", {"courier", "cancel", "job-1"});
  EXPECT_EQ(cancelled, 0) << cancel_out;
  EXPECT_NE(cancel_out.find("accepted: cancel job-1"), std::string::npos) << cancel_out;
  release_world();
  const auto [listed, jobs_out] = cli("jobs", {"courier", "jobs"});
  EXPECT_EQ(listed, 0) << jobs_out;
  EXPECT_NE(jobs_out.find("job-1"), std::string::npos) << jobs_out;
  EXPECT_NE(jobs_out.find("cancelled"), std::string::npos) << jobs_out;
}

// Learning from experience: the paper's two deliveries teach handover times of the two people
// and what the doors looked like; the courier keeps that in its journal when it stops, prints it
// with `autonomy courier knowledge`, and starts the next run with it.
TEST_F(CourierTest, WhatWasLearnedIsKeptInTheJournalAcrossRunsAndPrinted) {
  setup_observers(167);
  start_world(office_scenario(""));
  send_paper_commands();
  ASSERT_TRUE(both_jobs_finished("both jobs finished"));
  stop_watching(*courier_);
  courier_->signal(SIGTERM);
  ASSERT_TRUE(courier_->wait_for_exit(30s));
  const auto cli = [&](const std::string& name, std::vector<std::string> args) {
    ChildProcess& p = start(name, AUTONOMY_AUTONOMY_BIN, args, false);
    const auto status = p.wait_for_exit(30s);
    EXPECT_TRUE(status && status->exited) << name << " did not end";
    return std::make_pair(status && status->exited ? status->code : -1, read_file(p.log_file()));
  };
  const auto [code, out] = cli("knowledge", {"courier", "knowledge", journal_, "--json"});
  ASSERT_EQ(code, 0) << out;
  const auto learned = nlohmann::json::parse(out.substr(out.find('{')));
  // Four handovers: the load and unload of each job, with the people of the two desks and
  // the stations; each lasted about the scenario's handover time (seconds, not zero, not hours).
  ASSERT_TRUE(learned.contains("handovers")) << out;
  int handovers = 0;
  for (const auto& [person, stats] : learned["handovers"].items()) {
    handovers += stats["n"].get<int>();
    EXPECT_GT(stats["mean_s"].get<double>(), 0.5) << person;
    EXPECT_LT(stats["mean_s"].get<double>(), 300.0) << person;
  }
  EXPECT_GE(handovers, 2) << out;
  EXPECT_TRUE(learned["handovers"].contains("Michael")) << out;  // the red letter's recipient, A-120
  // A-120 was passed open: one open vote in the half hour of the run.
  ASSERT_TRUE(learned.contains("doors") && learned["doors"].contains("A-120")) << out;
  EXPECT_GE(learned["doors"]["A-120"][0]["open"].get<int>(), 1) << out;
  EXPECT_EQ(learned["doors"]["A-120"][0]["closed"].get<int>(), 0) << out;
  // Words for people too.
  const auto [text_code, text] = cli("knowledge-text", {"courier", "knowledge", journal_});
  EXPECT_EQ(text_code, 0);
  EXPECT_NE(text.find("Handover times"), std::string::npos) << text;
  EXPECT_NE(text.find("Michael"), std::string::npos) << text;
  // A bad path says so.
  const auto [bad, bad_out] = cli("knowledge-bad", {"courier", "knowledge", dir().file("none.db")});
  EXPECT_NE(bad, 0);
  // The next run starts with it.
  ChildProcess& again = start_courier("courier-again");
  ASSERT_TRUE(await("the restarted courier loaded what was learned", [&] {
    return read_file(again.log_file()).find("learning: 2 people") != std::string::npos ||
           read_file(again.log_file()).find("learning: 3 people") != std::string::npos ||
           read_file(again.log_file()).find("learning: 4 people") != std::string::npos;
  })) << read_file(again.log_file());
  EXPECT_EQ(read_file(again.log_file()).find("learning: 0 people"), std::string::npos);
}

TEST_F(CourierTest, ARobotAttachedWhileJobsRunGetsWork) {
  setup_observers(190);
  start_world(office_scenario("", fleet_extra()));
  send_fleet_jobs();
  // rhino alone takes all three; the world goes on until it has loaded its first object.
  ASSERT_TRUE(step_until("rhino loads something", [&] {
    for (const auto& o : objects_->all())
      if (o.carrier == "rhino") return true;
    return false;
  }));
  for (const char* job : {"job-1", "job-2", "job-3"}) EXPECT_FALSE(finished(job)) << job << job_story(job);
  for (const auto& s : jobs_->all()) EXPECT_NE(s.robot_id, "rhino2") << s.job_id;
  // rhino2 attaches while the jobs run; the world steps on (the test acknowledging) until its
  // behavior says ready, then runs free.
  ChildProcess& rhino2 = start_rhino2();
  ASSERT_TRUE(step_until("rhino2's behavior ready", [&] {
    beats_->poll();
    return !beats_->matching([&](const msg::Heartbeat& h) {
                   return h.pid == rhino2.pid() && h.state == msg::ServiceState::Ready;
                 })
                .empty();
  }));
  EXPECT_FALSE(beats_->matching([&](const msg::Heartbeat& h) { return h.pid == rhino2.pid(); })
                   .back()
                   .capabilities.empty());
  release_world();
  ASSERT_TRUE(jobs_finished({"job-1", "job-2", "job-3"}, "the three jobs finished"));
  for (const char* job : {"job-1", "job-2", "job-3"}) EXPECT_TRUE(job_in(job, msg::JobState::Completed)) << job << job_story(job);
  // rhino2 got work: an east parcel went aboard it, and its job said why rhino2.
  bool carried = false;
  for (const auto& o : objects_->all()) carried |= o.carrier == "rhino2";
  EXPECT_TRUE(carried);
  bool explained = false;
  std::string allocations;
  for (const auto& s : jobs_->all()) {
    if (!s.allocation.empty()) allocations += s.job_id + ": " + s.allocation + "\n";
    explained |= s.robot_id == "rhino2" && s.allocation.rfind("assigned to rhino2: ", 0) == 0;
  }
  EXPECT_TRUE(explained) << allocations;
  EXPECT_TRUE(object_tick("parcel-e1", "", "a112-desk"));
  EXPECT_TRUE(object_tick("parcel-e2", "", "a119-desk"));
  EXPECT_TRUE(object_tick("letter-3", "", "librarian-desk"));
}

TEST_F(CourierTest, ARobotKilledMidDeliveryHasItsJobsReallocatedAndItsParcelReportedStranded) {
  setup_observers(191);
  start_world(office_scenario("", fleet_extra()), {"behavior/rhino2"});
  ChildProcess& rhino2 = start_rhino2();
  send_fleet_jobs();
  ASSERT_TRUE(await_ready(*beats_, rhino2));
  // Both east parcels are rhino2's (it starts beside them), the letter rhino's. Step until rhino2
  // has loaded one of them, and kill its behavior right there.
  std::string aboard;
  ASSERT_TRUE(step_until("rhino2 loads a parcel", [&] {
    for (const auto& o : objects_->all())
      if (o.carrier == "rhino2") aboard = o.object_id;
    return !aboard.empty();
  }));
  const std::string other = aboard == "parcel-e1" ? "parcel-e2" : "parcel-e1";
  const std::string stranded_job = aboard == "parcel-e1" ? "job-1" : "job-2";
  const std::string other_job = aboard == "parcel-e1" ? "job-2" : "job-1";
  EXPECT_FALSE(object_tick(other, "rhino2", "")) << "both parcels aboard at once: nothing left to reallocate";
  bool other_was_rhino2s = false;
  for (const auto& s : jobs_->all()) other_was_rhino2s |= s.job_id == other_job && s.robot_id == "rhino2";
  EXPECT_TRUE(other_was_rhino2s) << job_story(other_job);
  stop_watching(rhino2);
  rhino2.signal(SIGKILL);
  ASSERT_TRUE(rhino2.wait_for_exit(10s));
  release_world();

  // The parcel aboard: reported stranded with where rhino2 was last seen, and not forgotten.
  ASSERT_TRUE(await("the parcel reported stranded", [&] {
    poll();
    return job_in(stranded_job, msg::JobState::Stranded).has_value();
  }, kRun)) << job_story(stranded_job);
  const auto stranded = job_in(stranded_job, msg::JobState::Stranded);
  EXPECT_NE(stranded->reason.find(aboard + " stranded aboard rhino2, last seen at ("), std::string::npos)
      << stranded->reason;
  EXPECT_NE(stranded->reason.find("heartbeat lost"), std::string::npos) << stranded->reason;
  EXPECT_EQ(stranded->robot_id, "rhino2");
  // The other parcel's job went to rhino, which delivers it along with its own letter.
  ASSERT_TRUE(jobs_finished({other_job, "job-3"}, "the other jobs finished"));
  EXPECT_TRUE(job_in(other_job, msg::JobState::Completed)) << job_story(other_job);
  EXPECT_TRUE(job_in("job-3", msg::JobState::Completed)) << job_story("job-3");
  EXPECT_TRUE(object_tick(other, "rhino", ""));
  EXPECT_FALSE(finished(stranded_job)) << job_story(stranded_job);
  // The courier's own account: rhino2 left, the queued job reallocated, the parcel stranded.
  std::set<std::string> kinds;
  for (const auto& [kind, line] : events()) kinds.insert(kind);
  for (const char* kind : {"robot_joined", "robot_left", "reallocated", "stranded"})
    EXPECT_TRUE(kinds.count(kind)) << kind;
}

}  // namespace
}  // namespace autonomy::test
