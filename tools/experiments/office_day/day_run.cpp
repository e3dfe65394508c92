#include "tools/experiments/office_day/day_run.hpp"

#include <google/protobuf/text_format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <csignal>
#include <fstream>
#include <limits>
#include <list>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "common/dds/participant.hpp"
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"
#include "common/process/child_process.hpp"
#include "tools/experiments/office_day/on_time_bound.hpp"

namespace autonomy::office_day {

namespace fs = std::filesystem;
using process::ChildProcess;

namespace {

constexpr char kName[] = "experiment/commands";
// After a command the stream keeps the world publishing for a while, so that the courier reads
// the command on a published tick as it would without quiet ticks.
constexpr int64_t kAwakeAfterCommandTicks = 20;

void stop(ChildProcess& child) {
  if (!child.running()) return;
  child.signal(SIGTERM);
  child.wait_for_exit(std::chrono::seconds(5));
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The courier's events file: what the counts of a day are made of.
DayCounts count_events(const fs::path& events) {
  DayCounts c;
  std::ifstream in(events);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto e = nlohmann::json::parse(line, nullptr, false);
    if (e.is_discarded() || !e.contains("kind")) continue;
    const std::string kind = e["kind"].get<std::string>();
    const std::string text = e.value("text", "");
    if (kind == "goal_blocked") {
      ++c.door_blocks;
      if (text.find("waiting to try again") != std::string::npos) c.door_wait_s += 10.0;
    }
    if (kind == "door_closed") ++c.doors_seen_closed;
    if (kind == "handover_refused") ++c.handover_refusals;
    if (kind == "opportunity_taken") ++c.opportunities;
  }
  return c;
}

}  // namespace

fs::path day_file(const RunSetup& setup, const std::string& strategy, int day, const std::string& what) {
  return setup.out_dir / "days" / (strategy + "-" + std::to_string(day) + "." + what);
}

DayRecord run_day(const RunSetup& setup, const Strategy& strategy, const DayPlan& plan, int day, std::uint64_t seed,
                  int domain, const fs::path& journal) {
  fs::create_directories(setup.out_dir / "days");
  fs::create_directories(setup.out_dir / "logs");
  const fs::path scenario = day_file(setup, strategy.id, day, "pbtxt");
  const fs::path events = day_file(setup, strategy.id, day, "events.jsonl");
  const fs::path metrics = day_file(setup, strategy.id, day, "metrics");
  std::string text;
  google::protobuf::TextFormat::PrintToString(plan.scenario, &text);
  std::ofstream(scenario) << "# " << strategy.id << " day " << day << " (seed " << seed << "), written by office_day\n"
                          << text;
  fs::remove(events);
  const std::string stem = strategy.id + "-" + std::to_string(day);
  const auto log = [&](const std::string& who) { return (setup.out_dir / "logs" / (stem + "-" + who + ".out")).string(); };
  const auto bin = [&](const char* program) { return (fs::path(setup.bin_dir) / program).string(); };
  const std::string dom = std::to_string(domain), logs = (setup.out_dir / "logs").string();
  const double step_s = plan.scenario.simulation().step_s();
  const long ticks = static_cast<long>(setup.day_s / step_s);

  std::vector<std::string> sim_args = {"--config", scenario.string(), "--domain", dom, "--log-dir", logs,
                                       "--max-ticks", std::to_string(ticks), "--metrics", metrics.string(),
                                       "--wait-for", "courier/main", "--wait-for", kName};
  for (const auto& r : plan.scenario.robots()) sim_args.insert(sim_args.end(), {"--wait-for", "behavior/" + r.id()});
  if (setup.every_tick) sim_args.push_back("--every-tick");
  if (setup.trajectory) sim_args.insert(sim_args.end(), {"--trajectory", day_file(setup, strategy.id, day, "trajectory.csv").string()});
  std::list<ChildProcess> children;
  ChildProcess& sim = children.emplace_back("simulator", bin("simulator"), sim_args, std::map<std::string, std::string>{}, log("simulator"));
  for (const auto& r : plan.scenario.robots())
    children.emplace_back("behavior-" + r.id(), bin("behavior"),
                          std::vector<std::string>{"--robot", r.id(), "--config", scenario.string(), "--domain", dom,
                                                   "--log-dir", logs},
                          std::map<std::string, std::string>{}, log("behavior-" + r.id()));
  std::vector<std::string> courier_args = {"--config", scenario.string(), "--journal", journal.string(), "--events",
                                           events.string(), "--domain", dom, "--log-dir", logs};
  courier_args.insert(courier_args.end(), strategy.courier_args.begin(), strategy.courier_args.end());
  ChildProcess& courier = children.emplace_back("courier", bin("courier"), courier_args, std::map<std::string, std::string>{}, log("courier"));

  // The office's people: send each command at its time, acknowledge every tick.
  dds::Participant participant(domain);
  dds::Topic<msg::SimClock> clock_topic(participant, dds::topics::clock);
  dds::Topic<msg::LockstepRegistration> registration_topic(participant, dds::topics::lockstep_registration);
  dds::Topic<msg::TickAck> ack_topic(participant, dds::topics::tick_ack);
  dds::Topic<msg::CourierCommand> command_topic(participant, dds::topics::courier_command);
  dds::Topic<msg::CourierJobStatus> status_topic(participant, dds::topics::courier_job_status);
  dds::Topic<msg::CourierSchedule> schedule_topic(participant, dds::topics::courier_schedule);
  dds::Reader<msg::SimClock> clock_reader(participant, clock_topic);
  dds::Reader<msg::CourierJobStatus> status_reader(participant, status_topic);
  dds::Reader<msg::CourierSchedule> schedule_reader(participant, schedule_topic);
  // Every change of every door (the ground truth), for the day's on-time bound: the reader keeps
  // a door's changes until taken, where the topic's own state QoS would keep only the last.
  dds::Topic<msg::DoorState> door_topic(participant, dds::topics::truth_door);
  dds::Qos door_qos = dds::make_qos(dds::QosClass::State);
  dds_qset_history(door_qos.get(), DDS_HISTORY_KEEP_LAST, 256);
  dds::Reader<msg::DoorState> door_reader(participant, door_topic, door_qos.get());
  DoorHistory doors;
  dds::Writer<msg::LockstepRegistration> registration(participant, registration_topic);
  dds::Writer<msg::TickAck> ack(participant, ack_topic);
  dds::Writer<msg::CourierCommand> commands(participant, command_topic);
  dds::WaitSet waitset(participant);
  waitset.attach(clock_reader.data_condition(), 1);
  registration.write({kName, true});

  std::map<std::string, msg::CourierJobStatus> jobs;  // job id -> latest
  int schedules = 0;
  std::size_t next = 0;
  int64_t acked = -1;
  int64_t awake_until = 0;
  // The first tick at which a command due at `at_s` is sent (the loop below: at_s <= now).
  const auto tick_of = [&](double at_s) { return static_cast<int64_t>(std::ceil(at_s / step_s - 1e-9)); };
  const auto started = std::chrono::steady_clock::now();
  const auto collect = [&] {
    for (auto& s : status_reader.take())
      if (s.valid) jobs[s.value.job_id] = s.value;
    for (auto& s : schedule_reader.take())
      if (s.valid) ++schedules;
    for (auto& s : door_reader.take())
      if (s.valid) doors.observe(s.value.door_id, static_cast<double>(s.value.tick) * step_s, s.value.closed);
  };
  while (sim.running()) {
    if (std::chrono::steady_clock::now() - started > setup.timeout) {
      for (auto& c : children) stop(c);
      throw std::runtime_error("day " + stem + " did not end within " + std::to_string(setup.timeout.count()) +
                               " s; see " + log("simulator"));
    }
    for (auto& c : children)
      if (&c != &sim && !c.running())
        throw std::runtime_error(c.name() + " of day " + stem + " ended (" + c.status()->describe() + "); see " +
                                 log(c.name()));
    waitset.wait(std::chrono::milliseconds(100));
    std::optional<msg::SimClock> latest;
    for (auto& s : clock_reader.take())
      if (s.valid && (!latest || s.value.tick > latest->tick)) latest = s.value;
    collect();
    if (!latest || latest->tick <= acked) continue;
    const double now_s = static_cast<double>(latest->sim_time_ns) * 1e-9;
    for (; next < plan.commands.size() && plan.commands[next].at_s <= now_s; ++next) {
      const DayCommand& c = plan.commands[next];
      msg::CourierCommand m;
      m.command_id = c.command_id;
      m.requester = "office_day";
      m.kind = msg::CourierCommandKind::Deliver;
      m.object_id = c.object_id;
      m.from = c.from;
      m.to = c.to;
      m.deadline = c.deadline;
      commands.write(m);
      awake_until = latest->tick + kAwakeAfterCommandTicks;
    }
    acked = latest->tick;
    int64_t quiet_until = 0;  // idl/clock.idl: nothing to send before the next command
    if (acked >= awake_until)
      quiet_until = next < plan.commands.size() ? tick_of(plan.commands[next].at_s) : std::numeric_limits<int64_t>::max();
    ack.write({kName, acked, 0, quiet_until});
  }
  const auto wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  if (!sim.status() || !sim.status()->exited || sim.status()->code != 0)
    throw std::runtime_error("the simulator of day " + stem + " failed; see " + log("simulator"));
  // The courier's last answers, then it stops (and saves what it learned).
  const auto settle = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  while (std::chrono::steady_clock::now() < settle) {
    collect();
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  registration.write({kName, false});
  stop(courier);
  for (auto& c : children) stop(c);

  const double day_start = clock_seconds(plan.scenario.day_start().empty() ? "08:30" : plan.scenario.day_start());
  std::map<std::string, JobOutcome> outcomes;
  for (const auto& [id, s] : jobs) {
    JobOutcome o{msg::to_string(s.state), 0};
    if (!s.estimated_completion.empty()) o.completion_s = clock_seconds(s.estimated_completion) - day_start;
    outcomes[s.command_id] = o;
  }
  DayRecord r = summarize(plan.commands, outcomes, setup.day_s);
  // The ceiling over the same jobs (those the courier accepted); the ones no fleet could have
  // done on time are listed with what stopped them.
  std::ofstream bound_file(day_file(setup, strategy.id, day, "impossible.txt"));
  for (const JobBound& b : on_time_bound(plan, doors.closures(), setup.day_s)) {
    if (!outcomes.count(b.command_id)) continue;
    if (b.possible) ++r.possible_on_time;
    else bound_file << b.command_id << ": " << b.why << "\n";
  }
  r.possible_percent = r.jobs ? 100.0 * r.possible_on_time / r.jobs : 0;
  r.strategy = strategy.id;
  r.day = day;
  r.seed = seed;
  r.counts = count_events(events);
  r.counts.reschedules = schedules;
  r.wall_s = wall;
  const auto m = nlohmann::json::parse(read_text(metrics.string() + ".json"), nullptr, false);
  if (!m.is_discarded() && m.contains("team")) r.distance_m = m["team"].value("distance_m", 0.0);
  return r;
}

}  // namespace autonomy::office_day
