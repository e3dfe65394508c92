// autonomy node wait: block until named processes report ready in their heartbeats.
#include <cstdio>
#include <iostream>
#include <memory>

#include "common/dds/topics.hpp"
#include "common/service/heartbeat.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/processes.hpp"

namespace autonomy::tools {

namespace {

struct WaitOptions {
  int domain = 0;
  std::vector<std::string> targets;
  double timeout_s = 20.0;
  // The launcher's own child: only the heartbeat of this pid on this host counts, so that a
  // process of the same name from another set on the domain is not taken for it.
  int32_t pid = 0;
};

struct Target {
  std::string service, instance;
  bool reported_ready = false;
  bool reported_other = false;  // said once that a same-named process of another pid is not it
  std::string name() const { return service + "/" + instance; }
};

int run_wait(const WaitOptions& o, Context& ctx) {
  std::vector<Target> targets;
  for (const auto& t : o.targets) {
    const auto slash = t.find('/');
    Target target{t.substr(0, slash), slash == std::string::npos ? "main" : t.substr(slash + 1)};
    if (target.service.empty() || target.instance.empty()) {
      std::cerr << "autonomy node wait: \"" << t << "\" is not SERVICE/INSTANCE (or SERVICE for SERVICE/main)\n";
      return kExitUsage;
    }
    targets.push_back(target);
  }
  if (o.pid != 0 && targets.size() != 1) {
    std::cerr << "autonomy node wait: --pid names the process of one SERVICE/INSTANCE, not of " << targets.size()
              << "\n";
    return kExitUsage;
  }
  const std::string this_host = service::host_name();
  const auto start = std::chrono::steady_clock::now();
  const auto deadline = start + seconds(o.timeout_s);

  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::Heartbeat> topic(participant, dds::topics::heartbeat);
  dds::Reader<msg::Heartbeat> reader(participant, topic);
  dds::WaitSet waitset(participant);
  waitset.attach(reader.data_condition(), 1);
  waitset.attach(interrupt.condition(), 2);

  ProcessTable table;
  for (;;) {
    table.update(reader.take());
    size_t ready = 0;
    for (auto& t : targets) {
      const ProcessView* p = table.find(t.service, t.instance);
      if (o.pid != 0) {
        p = nullptr;
        for (const auto& [key, row] : table.rows()) {
          if (key.service != t.service || key.instance != t.instance) continue;
          if (key.pid == o.pid && key.host == this_host) {
            p = &row;
          } else if (row.ready() && !t.reported_other) {
            std::cerr << "autonomy node wait: " << t.name() << " (pid " << key.pid << " on " << key.host
                      << ") is ready but is not the process awaited (pid " << o.pid << " on " << this_host
                      << "): another set on this domain?\n";
            t.reported_other = true;
          }
        }
      }
      const bool now_ready = p && p->ready();
      if (now_ready && !t.reported_ready) {
        char line[512];
        std::snprintf(line, sizeof(line), "%s ready (pid %d on %s, after %.2f s)", t.name().c_str(), p->last.pid,
                      p->last.host.c_str(),
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        print_line(line);
      } else if (!now_ready && t.reported_ready) {
        std::cerr << "autonomy node wait: " << t.name() << " no longer ready (" << (p ? p->state() : "gone") << ")\n";
      }
      t.reported_ready = now_ready;
      ready += now_ready ? 1 : 0;
    }
    if (ready == targets.size()) return kExitOk;
    if (interrupt.requested()) return kExitInterrupted;
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::nanoseconds::zero()) {
      std::cerr << "autonomy node wait: timeout after " << o.timeout_s << " s; not ready:";
      const char* separator = " ";
      for (const auto& t : targets) {
        if (t.reported_ready) continue;
        const ProcessView* p = table.find(t.service, t.instance);
        std::cerr << separator << t.name() << " (" << (p ? "last state: " + p->state() : std::string("never seen"))
                  << ")";
        separator = ", ";
      }
      std::cerr << "\n";
      return kExitFailed;
    }
    waitset.wait(left);
  }
}

}  // namespace

Command add_node_wait(CLI::App& node) {
  auto o = std::make_shared<WaitOptions>();
  auto* cmd = node.add_subcommand(
      "wait",
      "Wait until every named process's heartbeat says ready; print one line per process as it becomes ready. "
      "For launch scripts: `autonomy node wait simulator/main behavior/r1 --timeout 20`.");
  add_domain_option(cmd, o->domain);
  cmd->add_option("process", o->targets, "SERVICE/INSTANCE, e.g. behavior/r1 (SERVICE alone means SERVICE/main)")
      ->required();
  cmd->add_option("--pid", o->pid,
                  "Only the process of this pid on this host counts (a launcher awaiting its own child): a process "
                  "of the same name elsewhere on the domain is reported, not taken for it")
      ->check(CLI::PositiveNumber);
  cmd->add_option("-t,--timeout", o->timeout_s, "Seconds to wait")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer(
      "Exit codes: 0 all ready; 1 timeout (the missing ones and their last state on stderr), or DDS error; "
      "2 bad arguments; 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) { return run_wait(*o, ctx); }};
}

}  // namespace autonomy::tools
