// The viewer process (services/viewer) following 100 robots at 10 Hz with three pages connected:
// its CPU share of one core and the update latency a page sees.
//
// This bench is the world: one DDS participant publishes a 100 x 100 m map with obstacles and
// doors, then the states of --robots robots (each on its own circle) every 0.1 s, and door states
// that change now and then. The real viewer runs as a child (--rate 10). Three WebSocket clients
// (threads of this bench, tests/support/web_socket_client.hpp) read its frames like pages.
//
// Figures, over a fixed wall-time window after a warm-up, in two phases of the same run:
//   - baseline: no page connected (the viewer reads DDS, keeps its world and still builds a
//     frame per change at its rate, for /state.json and pages to come);
//   - three pages connected (sending the frames on top).
// For each: the viewer's CPU time (user + system, all threads, /proc/PID/stat) as a share of one
// core; frames per second each page received; update latency = a frame's arrival at a page minus
// the wall time the newest robot state in it was published (p50, p95, max), which includes the
// wait for the viewer's next frame (up to 1 / rate); frame size. Also in-process: the time to
// build and serialise one state frame of this world (WorldView + state_frame().dump()).
//
// Usage: viewer_bench [--domain 205] [--robots 100] [--seconds 10] [--warmup 2] [--pages 3]
// Needs the viewer next to this program (build/bin). Uses DDS domain --domain only.
#include "bench/bench_support.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "services/viewer/core/frames.hpp"
#include "tests/support/web_socket_client.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>
#include <thread>
#include <unistd.h>

using namespace autonomy;
using namespace autonomy::bench;

namespace {

struct ViewerBenchOptions {
  int domain = 205;
  int robots = 100;
  double seconds = 10.0;
  double warmup_s = 2.0;
  int pages = 3;
};

double viewer_bench_cpu_seconds(pid_t pid) {
  std::ifstream f("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(f, line)) return 0.0;
  std::istringstream in(line.substr(line.rfind(')') + 2));
  std::string field;
  unsigned long long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && in >> field; ++i) {
    if (i == 14) utime = std::stoull(field);
    if (i == 15) stime = std::stoull(field);
  }
  return static_cast<double>(utime + stime) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

msg::WorldMap viewer_bench_map() {
  msg::WorldMap m;
  m.name = "viewer-bench";
  m.width = 100.0;
  m.height = 100.0;
  for (int i = 0; i < 40; ++i) {
    const double x = 5.0 + (i % 8) * 12.0, y = 5.0 + (i / 8) * 19.0;
    m.obstacles.push_back({x, y, x + 2.0, y + 6.0});
  }
  for (int i = 0; i < 10; ++i)
    m.doors.push_back({"door-" + std::to_string(i), 6.0 + i * 9.0, 50.0, 1.0, 0.0, 1.5707963267948966});
  return m;
}

msg::RobotState viewer_bench_robot(int i, int64_t tick) {
  msg::RobotState s;
  s.robot_id = "robot-" + std::to_string(i);
  s.tick = tick;
  s.sim_time_ns = tick * 100'000'000;
  const double cx = 10.0 + (i % 10) * 9.0, cy = 10.0 + (i / 10) * 9.0;
  const double a = 0.05 * static_cast<double>(tick) + i;
  s.x = cx + 3.0 * std::cos(a);
  s.y = cy + 3.0 * std::sin(a);
  s.theta = a + 1.5707963267948966;
  s.vx = -0.15 * std::sin(a);
  s.vy = 0.15 * std::cos(a);
  s.radius = 0.3;
  return s;
}

// Per page: arrival latencies (s), frames and bytes, collected while `measuring`.
struct PageFigures {
  std::vector<double> latencies;
  uint64_t frames = 0;
  uint64_t bytes = 0;
};

struct Phase {
  double cpu_share = 0.0;
  std::vector<PageFigures> pages;
  double seconds = 0.0;
};

void print_phase(const char* name, const Phase& p) {
  std::printf("%-18s viewer CPU %5.1f %% of one core", name, 100.0 * p.cpu_share);
  if (p.pages.empty()) {
    std::printf("\n");
    return;
  }
  std::vector<double> all;
  uint64_t frames = 0, bytes = 0;
  for (const auto& page : p.pages) {
    all.insert(all.end(), page.latencies.begin(), page.latencies.end());
    frames += page.frames;
    bytes += page.bytes;
  }
  const double per_page_fps = static_cast<double>(frames) / static_cast<double>(p.pages.size()) / p.seconds;
  std::printf("; per page %.1f frames/s, %.1f kB/frame; latency p50 %.1f ms, p95 %.1f ms, max %.1f ms\n",
              per_page_fps, frames ? static_cast<double>(bytes) / static_cast<double>(frames) / 1e3 : 0.0,
              1e3 * percentile(all, 50), 1e3 * percentile(all, 95), 1e3 * percentile(all, 100));
}

}  // namespace

int main(int argc, char** argv) {
  ViewerBenchOptions o;
  CLI::App app{"The viewer with 100 robots at 10 Hz and three pages: CPU share and update latency"};
  app.add_option("--domain", o.domain, "DDS domain")->check(CLI::Range(0, 232));
  app.add_option("--robots", o.robots, "Robots published")->check(CLI::Range(1, 10000));
  app.add_option("--seconds", o.seconds, "Measured window per phase, s")->check(CLI::Range(1.0, 600.0));
  app.add_option("--warmup", o.warmup_s, "Warm-up before each phase, s")->check(CLI::Range(0.0, 60.0));
  app.add_option("--pages", o.pages, "Pages connected in the second phase")->check(CLI::Range(1, 50));
  CLI11_PARSE(app, argc, argv);
  if (!std::getenv("CYCLONEDDS_URI"))
    progress("note: CYCLONEDDS_URI is not set; Cyclone picks its default network interface");

  // In-process baseline: build and serialise one state frame of this world.
  {
    viewer::WorldView view;
    view.apply(viewer_bench_map());
    for (int64_t tick = 0; tick < 100; ++tick)
      for (int i = 0; i < o.robots; ++i) view.apply(viewer_bench_robot(i, tick));
    std::vector<double> build_ms;
    std::size_t size = 0;
    for (int n = 0; n < 50; ++n) {
      const auto t0 = Clock::now();
      size = viewer::state_frame(view, static_cast<uint64_t>(n)).dump().size();
      build_ms.push_back(1e3 * seconds_since(t0));
    }
    std::printf("in-process: one state frame of %d robots (full tails): %.2f ms to build and serialise "
                "(median of 50), %.1f kB\n",
                o.robots, median(build_ms), static_cast<double>(size) / 1e3);
  }

  dds::Participant participant(o.domain);
  dds::Topic<msg::WorldMap> map_topic(participant, dds::topics::world_map);
  dds::Writer<msg::WorldMap> map_writer(participant, map_topic);
  dds::Topic<msg::RobotState> robot_topic(participant, dds::topics::robot_state);
  dds::Writer<msg::RobotState> robot_writer(participant, robot_topic);
  dds::Topic<msg::DoorState> door_topic(participant, dds::topics::truth_door);
  dds::Writer<msg::DoorState> door_writer(participant, door_topic);
  map_writer.write(viewer_bench_map());

  const std::string log = "/tmp/viewer_bench_" + std::to_string(getpid()) + ".log";
  ChildProcess viewer({self_dir() + "/viewer", "--domain", std::to_string(o.domain), "--port", "0", "--rate", "10",
                       "--log-level", "warn", "--log-dir", "/tmp"},
                      false, log);
  uint16_t port = 0;
  const std::regex address(R"(viewer: open http://127\.0\.0\.1:(\d+)/)");
  for (const auto t0 = Clock::now(); port == 0 && seconds_since(t0) < 20.0;) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    std::smatch m;
    if (std::regex_search(s, m, address)) port = static_cast<uint16_t>(std::stoi(m[1]));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (port == 0) {
    std::fprintf(stderr, "viewer_bench: the viewer did not print its address (log %s)\n", log.c_str());
    return 1;
  }
  if (!robot_writer.wait_for_readers(1, std::chrono::seconds(10))) {
    std::fprintf(stderr, "viewer_bench: the viewer does not read robot states\n");
    return 1;
  }

  // Publisher: every 0.1 s all robots; the wall time of each tick's publication, for latencies.
  std::mutex sent_mutex;
  std::map<int64_t, Clock::time_point> sent_at;
  std::atomic<bool> stop{false};
  std::thread publisher([&] {
    auto next = Clock::now();
    for (int64_t tick = 1; !stop; ++tick) {
      for (int i = 0; i < o.robots; ++i) robot_writer.write(viewer_bench_robot(i, tick));
      if (tick % 20 == 0) {
        msg::DoorState d;
        d.door_id = "door-" + std::to_string((tick / 20) % 10);
        d.tick = tick;
        d.closed = (tick / 20) % 2 == 0;
        d.angle = d.closed ? 0.0 : 1.2;
        door_writer.write(d);
      }
      {
        std::lock_guard<std::mutex> lock(sent_mutex);
        sent_at[tick] = Clock::now();
        if (sent_at.size() > 200) sent_at.erase(sent_at.begin());
      }
      next += std::chrono::milliseconds(100);
      std::this_thread::sleep_until(next);
    }
  });

  auto measure = [&](int pages) {
    std::vector<PageFigures> figures(static_cast<std::size_t>(pages));
    std::atomic<bool> measuring{false}, done{false};
    std::vector<std::thread> readers;
    for (int p = 0; p < pages; ++p) {
      readers.emplace_back([&, p] {
        test::WebSocketClient ws(port, "/ws");
        while (!done) {
          auto text = ws.next(std::chrono::milliseconds(200));
          if (!text || !measuring) continue;
          const auto arrived = Clock::now();
          const auto frame = nlohmann::json::parse(*text);
          if (frame["type"] != "state") continue;
          const int64_t tick = frame["tick"].get<int64_t>();
          std::lock_guard<std::mutex> lock(sent_mutex);
          const auto at = sent_at.find(tick);
          auto& f = figures[static_cast<std::size_t>(p)];
          ++f.frames;
          f.bytes += text->size();
          if (at != sent_at.end()) f.latencies.push_back(std::chrono::duration<double>(arrived - at->second).count());
        }
      });
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(o.warmup_s));
    const double cpu0 = viewer_bench_cpu_seconds(viewer.pid());
    const auto t0 = Clock::now();
    measuring = true;
    std::this_thread::sleep_for(std::chrono::duration<double>(o.seconds));
    measuring = false;
    Phase phase;
    phase.seconds = seconds_since(t0);
    phase.cpu_share = (viewer_bench_cpu_seconds(viewer.pid()) - cpu0) / phase.seconds;
    done = true;
    for (auto& t : readers) t.join();
    phase.pages = std::move(figures);
    return phase;
  };

  progress("viewer_bench: %d robots at 10 Hz, viewer on port %u, phase 1: no page", o.robots, port);
  const Phase idle = measure(0);
  progress("viewer_bench: phase 2: %d pages", o.pages);
  const Phase loaded = measure(o.pages);
  stop = true;
  publisher.join();
  std::printf("%d robots at 10 Hz, %.0f s per phase after %.0f s warm-up\n", o.robots, o.seconds, o.warmup_s);
  print_phase("no page (baseline)", idle);
  print_phase((std::to_string(o.pages) + " pages").c_str(), loaded);
  viewer.terminate();
  std::remove(log.c_str());
  return 0;
}
