// The kill matrix's courier sets (deploy/sets/courier.set, courier-fleet.set): the paper's two
// commands (the red letter to A-120, whose door closes at 15 s and opens at 40 s, and the green
// book), the blow once the first object is aboard a robot, and both jobs completed in the end.
// Domains and the matrix's rules: kill_matrix.hpp.
#include "tests/integration/courier_fixture.hpp"
#include "tests/integration/kill_matrix.hpp"

namespace autonomy::test {
namespace {

class CourierSetKillTest : public KillMatrixTest {
 protected:
  void SetUp() override {
    KillMatrixTest::SetUp();
    objects_.emplace(participant(), dds::topics::truth_object);
    jobs_.emplace(participant(), dds::topics::courier_job_status);
    replies_.emplace(participant(), dds::topics::courier_reply);
    command_topic_.emplace(participant(), dds::topics::courier_command);
    command_writer_.emplace(participant(), *command_topic_);
  }
  void poll() {
    objects_->poll();
    jobs_->poll();
    replies_->poll();
  }
  void send(const std::string& id, const std::string& text) { send_command_text(*command_writer_, id, text); }
  std::optional<msg::CourierJobStatus> last_of(const std::string& job) const {
    std::optional<msg::CourierJobStatus> last;
    for (const auto& s : jobs_->all())
      if (s.job_id == job) last = s;
    return last;
  }
  bool ended(const std::string& job) const {
    const auto s = last_of(job);
    return s && (s->state == msg::JobState::Completed || s->state == msg::JobState::Failed ||
                 s->state == msg::JobState::Cancelled);
  }
  std::string story(const std::string& job) const {
    std::string out = job + ":";
    for (const auto& s : jobs_->all())
      if (s.job_id == job)
        out += std::string(" -> ") + msg::to_string(s.state) + (s.phase.empty() ? "" : "/" + s.phase) +
               (s.reason.empty() ? "" : " (" + s.reason + ")") + "@" + std::to_string(s.tick);
    return out;
  }

  void run_the_paper_example(const std::string& set) {
    prepare(set);
    ASSERT_NO_FATAL_FAILURE(launch());
    send("c1", kRedLetter);
    send("c2", kGreenBook);
    ASSERT_TRUE(await("both commands answered", [&] {
      poll();
      return replies_->all().size() >= 2;
    }));
    for (const auto& r : replies_->all()) ASSERT_TRUE(r.accepted) << r.command_id << ": " << r.reason;
    ASSERT_TRUE(step_until("an object aboard a robot", [&] {
      poll();
      return std::any_of(objects_->all().begin(), objects_->all().end(),
                         [](const msg::ObjectState& o) { return !o.carrier.empty(); });
    }));
    ASSERT_NO_FATAL_FAILURE(blow());
    if (world_killed()) {
      ASSERT_NO_FATAL_FAILURE(expect_the_set_stopped_with_the_world());
      expect_the_journal_keeps_both_jobs();
      return;
    }
    ASSERT_TRUE(await("both jobs ended", [&] {
      poll();
      return ended("job-1") && ended("job-2");
    }, kMission)) << story("job-1") << "\n" << story("job-2") << "\n" << launcher_output();
    for (const char* job : {"job-1", "job-2"}) {
      const auto last = last_of(job);
      if (set == "courier-fleet" && last->state == msg::JobState::Failed) {
        // Two robots can still block each other head-on in the 2 m hall, whatever the blow (a
        // shifted schedule only changes when they meet): both goals end "no progress for 10 s".
        // That is fleet traffic (issue 25), not recovery: the job must end saying so (an object
        // aboard is taken back, as the courier's failure handling does).
        EXPECT_NE(last->reason.find("no progress for"), std::string::npos) << story(job);
        continue;
      }
      EXPECT_EQ(last->state, msg::JobState::Completed) << story(job);
    }
    expect_the_set_still_runs();
  }

  // Nothing accepted is lost with the world: a courier started on the set's journal has both jobs.
  void expect_the_journal_keeps_both_jobs() {
    jobs_->poll();
    const std::size_t before = jobs_->all().size();
    auto& courier = start("courier-after", AUTONOMY_COURIER_BIN,
                          {"--config", std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt", "--journal",
                           set_->file("courier.db"), "--domain", std::to_string(domain_), "--log-dir", dir().path()});
    ASSERT_TRUE(await("the journal's jobs published again", [&] {
      jobs_->poll();
      bool one = false, two = false;
      for (std::size_t i = before; i < jobs_->all().size(); ++i) {
        one |= jobs_->all()[i].job_id == "job-1";
        two |= jobs_->all()[i].job_id == "job-2";
      }
      return one && two;
    })) << courier.log_tail();
  }

  std::optional<Recorder<msg::ObjectState>> objects_;
  std::optional<Recorder<msg::CourierJobStatus>> jobs_;
  std::optional<Recorder<msg::CourierReply>> replies_;
  std::optional<dds::Topic<msg::CourierCommand>> command_topic_;
  std::optional<dds::Writer<msg::CourierCommand>> command_writer_;
};

TEST_P(CourierSetKillTest, Cell) { run_the_paper_example(GetParam().set); }

INSTANTIATE_TEST_SUITE_P(Sets, CourierSetKillTest,
                         ::testing::Values(Cell{"courier", "", Blow::none, 6},
                                           Cell{"courier", "simulator/main", Blow::kill, 7},
                                           Cell{"courier", "simulator/main", Blow::stop, 8},
                                           Cell{"courier", "behavior/rhino", Blow::kill, 9},
                                           Cell{"courier", "behavior/rhino", Blow::stop, 10},
                                           Cell{"courier", "courier/main", Blow::kill, 11},
                                           Cell{"courier", "courier/main", Blow::stop, 12},
                                           Cell{"courier-fleet", "", Blow::none, 13},
                                           Cell{"courier-fleet", "simulator/main", Blow::stop, 14},
                                           Cell{"courier-fleet", "behavior/rhino", Blow::kill, 15},
                                           Cell{"courier-fleet", "behavior/rhino2", Blow::kill, 16},
                                           Cell{"courier-fleet", "behavior/rhino2", Blow::stop, 17},
                                           Cell{"courier-fleet", "courier/main", Blow::kill, 18},
                                           Cell{"courier-fleet", "courier/main", Blow::stop, 19},
                                           Cell{"courier-fleet", "behavior/rhino", Blow::stop, 44},
                                           Cell{"courier-fleet", "simulator/main", Blow::kill, 45}),
                         cell_name);

}  // namespace
}  // namespace autonomy::test
