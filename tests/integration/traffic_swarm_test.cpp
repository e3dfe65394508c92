// A swarm on the office floor (docs/traffic.md, issue 25): ten robots, one behavior each, in
// lockstep with the real simulator, each sent seeded random goals one after another. The
// simulator's ground truth says no robot ever touched another (its trajectory, every robot every
// tick: no two centres closer than two radii plus 1 cm; its robot states: no in_collision beside another robot), and
// every goal ended reached or blocked with a reason within a bound of simulated time, or was still
// younger than that bound when the run ended: no deadlock.
//
// bench/swarm_bench.sh runs the same test with other sizes, durations and --no-traffic through
// the environment (SWARM_ROBOTS, SWARM_SIM_S, SWARM_TRAFFIC=0, SWARM_SEED, SWARM_WALL_S); without
// traffic it only reports (robots touch then). Every run prints one "swarm:" line with the figures.
//
// One DDS domain per test; this file uses 103 only:
//
//   domain  test
//   ------  -----------------------------------------------
//    103    TrafficSwarmTest.TenRobotsWithRandomGoalsNeverTouchNorDeadlock
#include "tests/support/goal_statuses.hpp"
#include "tests/support/process_test.hpp"

#include "common/geometry/shapes.hpp"
#include "simulator/scenario/scenario_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <thread>

namespace autonomy::test {
namespace {

using namespace std::chrono_literals;
using msg::GoalState;

const std::string kSwarmOffice = std::string(AUTONOMY_SOURCE_DIR) + "/deploy/scenarios/office.pbtxt";
constexpr double kSwarmRadius = 0.3;       // the office's couriers
constexpr double kSwarmStep_s = 0.1;       // the office's simulation step
constexpr double kSwarmGoalBound_s = 300;  // 90 s of waits in all plus the drive (the stall rule keeps it moving)

double swarm_env(const char* name, double fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::atof(v) : fallback;
}

bool swarm_ended(GoalState s) { return s != GoalState::Accepted && s != GoalState::Active; }

// Random points of the office where a robot's disc fits with the grid's margin (clear of walls,
// furniture and open door leaves) and that lie away from every doorway, so that no goal parks a
// robot in a passage; `apart` from the points already drawn when asked (start positions).
class SwarmPoints {
 public:
  SwarmPoints(const sim::Scenario& scenario, unsigned seed) : world_(scenario.world), rng_(seed) {}
  geometry::Vec2 draw(const std::vector<geometry::Vec2>& apart_from = {}, double apart = 0.0) {
    std::uniform_real_distribution<double> ux(0.0, world_.width), uy(0.0, world_.height);
    constexpr double kClear = 0.55;  // radius 0.3 + grid margin 0.1 + half a cell diagonal + slack
    for (;;) {
      const geometry::Vec2 p(ux(rng_), uy(rng_));
      bool fits = p.x() > kClear && p.y() > kClear && p.x() < world_.width - kClear && p.y() < world_.height - kClear;
      for (const auto& o : world_.obstacles) fits = fits && geometry::distance(o, p) >= kClear;
      for (const auto& d : world_.doors) {
        const auto leaf = d.leaf(d.angle);
        fits = fits && geometry::segment_distance(p, leaf.hinge, leaf.tip) >= kClear &&
               (p - d.position).norm() >= 1.3;
      }
      for (const auto& q : apart_from) fits = fits && (p - q).norm() >= apart;
      if (fits) return p;
    }
  }

 private:
  const sim::WorldSpec& world_;
  std::mt19937 rng_;
};

// The closest two robots came at one tick (centre distance) and at how many robot-ticks two were
// in contact, from the simulator's trajectory file (tick,time_s,robot,x,y,theta).
struct SwarmContacts {
  double closest_m = 1e9;
  std::string where;
  int contact_ticks = 0;
  int64_t ticks = 0;
};

SwarmContacts swarm_contacts(const std::string& csv) {
  SwarmContacts c;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  int64_t tick = -1;
  std::vector<std::pair<std::string, geometry::Vec2>> at;
  const auto judge = [&] {
    bool contact = false;
    for (std::size_t i = 0; i < at.size(); ++i)
      for (std::size_t j = i + 1; j < at.size(); ++j) {
        const double d = (at[i].second - at[j].second).norm();
        contact |= d < 2 * kSwarmRadius + 0.01;
        if (d < c.closest_m) {
          c.closest_m = d;
          c.where = at[i].first + " and " + at[j].first + " at tick " + std::to_string(tick);
        }
      }
    c.contact_ticks += contact ? 1 : 0;
  };
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string f[6];
    for (auto& x : f) std::getline(ss, x, ',');
    const int64_t t = std::atoll(f[0].c_str());
    if (t != tick) {
      judge();
      at.clear();
      tick = t;
      ++c.ticks;
    }
    at.emplace_back(f[2], geometry::Vec2(std::atof(f[3].c_str()), std::atof(f[4].c_str())));
  }
  judge();
  return c;
}

class TrafficSwarmTest : public ProcessTest {};

TEST_F(TrafficSwarmTest, TenRobotsWithRandomGoalsNeverTouchNorDeadlock) {
  const int robots = static_cast<int>(swarm_env("SWARM_ROBOTS", 10));
  // CI: 4 simulated minutes (about 40 s of wall time on two cores); the bench runs 30.
  const double sim_s = swarm_env("SWARM_SIM_S", 240);
  const bool traffic = swarm_env("SWARM_TRAFFIC", 1) != 0;
  const unsigned seed = static_cast<unsigned>(swarm_env("SWARM_SEED", 25));
  const auto wall = std::chrono::seconds(static_cast<int>(swarm_env("SWARM_WALL_S", 600)));
  ASSERT_GE(robots, 1);
  ASSERT_LE(robots, 20);
  join(static_cast<int>(swarm_env("SWARM_DOMAIN", 103)));
  const auto loaded = sim::load_scenario_file(kSwarmOffice);
  ASSERT_TRUE(loaded.ok()) << loaded.error_text();
  SwarmPoints points(*loaded.scenario, seed);

  Recorder<msg::Heartbeat> beats(participant(), dds::topics::heartbeat);
  Recorder<msg::RobotState> states(participant(), dds::topics::robot_state);
  Recorder<msg::GoalStatus> goals(participant(), dds::topics::goal_status);
  dds::Topic<msg::NavGoal> goal_topic(participant(), dds::topics::nav_goal);
  dds::Writer<msg::NavGoal> goal_writer(participant(), goal_topic);
  // --every-tick: no quiet ticks; a robot between goals holds the world like a busy one, so the
  // next goal arrives a few ticks after the last ended, not after a quiet stretch of minutes.
  std::vector<std::string> ids, sim_args{"--config", kSwarmOffice, "--without-robots", "--every-tick", "--max-ticks",
                                         std::to_string(static_cast<int64_t>(std::llround(sim_s / kSwarmStep_s))),
                                         "--trajectory", dir().file("trajectory.csv"), "--wait-for"};
  for (int i = 1; i <= robots; ++i) {
    ids.push_back("r" + std::to_string(i));
    sim_args.push_back("behavior/" + ids.back());
  }
  auto& simulator = start_simulator(sim_args, /*must_keep_running=*/false);
  std::vector<geometry::Vec2> starts;
  for (const auto& id : ids) {
    starts.push_back(points.draw(starts, 1.5));
    std::vector<std::string> args{"--start", std::to_string(starts.back().x()), std::to_string(starts.back().y()), "0"};
    if (!traffic) args.push_back("--no-traffic");
    start_behavior(id, args);
  }
  ASSERT_TRUE(goal_writer.wait_for_readers(robots, kDeadline));

  // Each robot gets its next goal as soon as its last one ended.
  struct Goal {
    std::string id;
    geometry::Vec2 at;
    int64_t sent_tick = 0;
    int64_t end_tick = -1;
    GoalState state = GoalState::Accepted;
    std::string reason;
  };
  std::map<std::string, std::vector<Goal>> sent;
  int64_t tick = 0;
  int collisions = 0;
  std::string collided;  // the first robot states that said in_collision
  const auto send_next = [&](const std::string& robot) {
    auto& v = sent[robot];
    Goal g;
    g.id = robot + "-g" + std::to_string(v.size());
    g.at = points.draw();
    g.sent_tick = tick;
    goal_writer.write({robot, g.id, g.at.x(), g.at.y(), 0.0, ""});
    v.push_back(g);
  };
  for (const auto& id : ids) send_next(id);
  const bool finished = await("the simulator's run of " + std::to_string(sim_s) + " s", [&] {
    // Polled every millisecond for 20 ms (await sleeps 20 ms between calls): the next goal goes out
    // within a few ticks of the last one's end.
    for (int spin = 0; spin < 20 && simulator.running(); ++spin) {
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
      for (const auto& s : goals.poll()) {
        auto& v = sent[s.robot_id];
        if (v.empty() || v.back().id != s.goal_id || v.back().end_tick >= 0 || !swarm_ended(s.state)) continue;
        v.back().end_tick = std::max(s.tick, v.back().sent_tick);
        v.back().state = s.state;
        v.back().reason = s.reason;
        send_next(s.robot_id);
      }
    }
    for (const auto& s : states.poll()) {
      tick = std::max(tick, s.tick);
      collisions += s.in_collision ? 1 : 0;
      if (s.in_collision && collided.size() < 400) {
        char b[96];
        std::snprintf(b, sizeof b, " %s at (%.2f, %.2f) tick %lld;", s.robot_id.c_str(), s.x, s.y,
                      static_cast<long long>(s.tick));
        collided += b;
      }
    }
    return !simulator.running();
  }, wall);
  ASSERT_TRUE(finished);
  states.poll();

  // The figures.
  int reached = 0, blocked = 0, open = 0, overdue = 0;
  double longest_s = 0.0;
  std::string reasons, overdue_text;
  std::map<std::string, int> reason_count;
  for (const auto& [robot, v] : sent)
    for (const auto& g : v) {
      const int64_t end = g.end_tick >= 0 ? g.end_tick : tick;
      const double took_s = static_cast<double>(end - g.sent_tick) * kSwarmStep_s;
      longest_s = std::max(longest_s, took_s);
      if (took_s > kSwarmGoalBound_s) {
        ++overdue;
        overdue_text += " " + g.id + " (" + std::to_string(took_s) + " s, " + msg::to_string(g.state) + ")";
      }
      if (g.end_tick < 0) {
        ++open;
      } else if (g.state == GoalState::Reached) {
        ++reached;
      } else {
        ++blocked;
        // The reason with its numbers blanked, to count kinds ("no progress for #.# s, #.# m from goal").
        std::string kind;
        for (const char ch : g.reason.substr(0, 90)) {
          const bool digit = ch >= '0' && ch <= '9';
          if (!digit || kind.empty() || kind.back() != '#') kind += digit ? '#' : ch;
        }
        ++reason_count[msg::to_string(g.state) + std::string(": ") + kind];
        if (g.reason.empty()) reasons += " " + g.id + " ended " + msg::to_string(g.state) + " without a reason;";
      }
    }
  const SwarmContacts c = swarm_contacts(dir().file("trajectory.csv"));
  // The in_collision states split by what stopped the robot: another robot (one within contact
  // distance at that tick) or the map (a wall, furniture, a door leaf).
  std::map<int64_t, std::vector<const msg::RobotState*>> collision_ticks;
  for (const auto& s : states.all())
    if (s.in_collision) collision_ticks[s.tick];
  for (const auto& s : states.all())
    if (const auto t = collision_ticks.find(s.tick); t != collision_ticks.end()) t->second.push_back(&s);
  int robot_collisions = 0;
  for (const auto& [t, v] : collision_ticks)
    for (const auto* a : v)
      if (a->in_collision && std::any_of(v.begin(), v.end(), [&](const msg::RobotState* b) {
            return b->robot_id != a->robot_id && std::hypot(a->x - b->x, a->y - b->y) < 2 * kSwarmRadius + 0.02;
          }))
        ++robot_collisions;
  const double hours = static_cast<double>(c.ticks) * kSwarmStep_s / 3600.0;
  std::printf(
      "swarm: robots %d  mode %s  sim %.0f s  goals reached %d  ended otherwise %d  open at the end %d  "
      "goals/hour %.1f  longest goal %.1f s  closest %.2f m  contact ticks %d  in_collision states %d (with a robot %d)\n",
      robots, traffic ? "traffic" : "no-traffic", static_cast<double>(c.ticks) * kSwarmStep_s, reached, blocked,
      open, hours > 0 ? reached / hours : 0.0, longest_s, c.closest_m, c.contact_ticks, collisions, robot_collisions);
  for (const auto& [kind, n] : reason_count) std::printf("swarm:   %3d x %s\n", n, kind.c_str());
  std::fflush(stdout);
  if (!traffic) return;  // the baseline only reports
  EXPECT_GT(reached, 0);
  EXPECT_GE(c.closest_m, 2 * kSwarmRadius + 0.01) << c.where;
  EXPECT_EQ(c.contact_ticks, 0) << c.where;
  EXPECT_EQ(robot_collisions, 0) << collided;
  // Stopped by the map (a wall, a door leaf): reported, not asserted; seen in about one run of
  // five, and not a matter of traffic (docs/traffic.md, "What is not solved").
  if (collisions > robot_collisions) std::printf("swarm: stopped by the map:%s\n", collided.c_str());
  EXPECT_EQ(overdue, 0) << "goals older than " << kSwarmGoalBound_s << " s:" << overdue_text;
  EXPECT_TRUE(reasons.empty()) << reasons;
}

}  // namespace
}  // namespace autonomy::test
