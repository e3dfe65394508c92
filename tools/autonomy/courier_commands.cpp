// autonomy courier send | jobs | cancel: the courier service from the shell, as `autonomy topic`
// is for topics. send and cancel write one CourierCommand and wait for its reply; jobs prints the
// latest state of every job (autonomy/courier/job_status is a state topic: a late reader gets it).
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <map>
#include <memory>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"
#include "tools/autonomy/commands.hpp"

namespace autonomy::tools {

namespace {

struct CommandOptions {
  int domain = 0;
  std::string text;
  std::string job;
  std::string id;
  double timeout_s = 10.0;
};

// The reply in words; for a rejected text command a caret under the word at fault.
void print_reply(const msg::CourierReply& r, const std::string& text) {
  if (r.accepted) {
    print_line(r.action == "deliver" ? "accepted as " + r.job_id + ": deliver " + r.object + " from " + r.from + " to " +
                                           r.to + (r.deadline.empty() ? "" : " by " + r.deadline)
                                     : "accepted: " + r.action + " " + r.job_id);
    for (const auto& a : r.assumptions) print_line("  assumed: " + a);
    return;
  }
  std::cerr << "rejected (" << r.reason << "): " << r.detail << "\n";
  if (r.column > 0 && !text.empty() && static_cast<size_t>(r.column) <= text.size() + 1)
    std::cerr << "  " << text << "\n  " << std::string(static_cast<size_t>(r.column - 1), ' ') << "^\n";
}

int send_and_wait(const CommandOptions& o, msg::CourierCommand command, Context& ctx) {
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::CourierCommand> command_topic(participant, dds::topics::courier_command);
  dds::Topic<msg::CourierReply> reply_topic(participant, dds::topics::courier_reply);
  dds::Reader<msg::CourierReply> replies(participant, reply_topic);
  dds::Writer<msg::CourierCommand> writer(participant, command_topic);
  const auto deadline = std::chrono::steady_clock::now() + seconds(o.timeout_s);
  // Requests are volatile: wait for the courier's reader, and for our reply reader to be matched.
  while (writer.matched_readers() == 0 || replies.matched_writers() == 0) {
    if (std::chrono::steady_clock::now() >= deadline) {
      std::cerr << "autonomy courier: no courier service on domain " << o.domain << " within " << o.timeout_s
                << " s (is it running? autonomy node list)\n";
      return kExitFailed;
    }
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(10))) return kExitInterrupted;
  }
  command.command_id = o.id.empty() ? "cli-" + std::to_string(getpid()) + "-" +
                                          std::to_string(std::chrono::steady_clock::now().time_since_epoch().count())
                                    : o.id;
  command.requester = "autonomy-cli";
  writer.write(command);
  ResendSchedule resend(std::chrono::steady_clock::now());
  dds::WaitSet waitset(participant);
  waitset.attach(replies.data_condition(), 1);
  waitset.attach(interrupt.condition(), 2);
  for (;;) {
    for (const auto& s : replies.take()) {
      if (!s.valid || s.value.command_id != command.command_id) continue;
      print_reply(s.value, command.text);
      return s.value.accepted ? kExitOk : kExitFailed;
    }
    if (interrupt.requested()) return kExitInterrupted;
    const auto now = std::chrono::steady_clock::now();
    const auto left = deadline - now;
    if (left <= std::chrono::nanoseconds::zero()) {
      std::cerr << "autonomy courier: no reply to " << command.command_id << " within " << o.timeout_s << " s\n";
      return kExitFailed;
    }
    if (resend.due(now)) {  // the courier journals every command id: a repeat gets the same reply
      writer.write(command);
      resend.resent(now);
    }
    waitset.wait(std::min(left, std::max(resend.next() - now, std::chrono::nanoseconds::zero())));
  }
}

int list_jobs(const CommandOptions& o, Context& ctx) {
  dds::Participant participant(o.domain);
  Interrupt interrupt(ctx.signals, participant);
  dds::Topic<msg::CourierJobStatus> topic(participant, dds::topics::courier_job_status);
  dds::Reader<msg::CourierJobStatus> reader(participant, topic);
  // The state topic's writer hands a late reader every job's latest state; give it a moment.
  std::map<std::string, msg::CourierJobStatus> jobs;
  const auto until = std::chrono::steady_clock::now() + seconds(o.timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    for (auto& s : reader.take())
      if (s.valid) jobs[s.value.job_id] = std::move(s.value);
    if (!sleep_for(interrupt, participant, std::chrono::milliseconds(50))) break;
  }
  if (jobs.empty()) {
    std::cerr << "autonomy courier jobs: no job states on domain " << o.domain << " within " << o.timeout_s << " s\n";
    return kExitFailed;
  }
  char line[512];
  std::snprintf(line, sizeof line, "%-8s %-13s %-15s %-7s %-14s %-16s %-8s %-9s %s", "JOB", "STATE", "PHASE", "ROBOT",
                "OBJECT", "TO", "DEADLINE", "ETA", "REASON");
  print_line(line);
  for (const auto& [id, j] : jobs) {
    // With several couriers, why this robot follows the reason.
    const std::string why = j.allocation.empty() ? j.reason : j.reason.empty() ? j.allocation : j.reason + "; " + j.allocation;
    std::snprintf(line, sizeof line, "%-8s %-13s %-15s %-7s %-14s %-16s %-8s %-9s %s", id.c_str(),
                  msg::to_string(j.state), j.phase.c_str(), j.robot_id.c_str(), j.object_id.c_str(), j.to.c_str(),
                  j.deadline.c_str(), j.estimated_completion.c_str(), why.c_str());
    print_line(line);
  }
  return kExitOk;
}

}  // namespace

Command add_courier_send(CLI::App& courier) {
  auto o = std::make_shared<CommandOptions>();
  auto* cmd = courier.add_subcommand(
      "send", "Send a delivery command in restricted English and print the courier's interpretation or rejection");
  add_domain_option(cmd, o->domain);
  cmd->add_option("text", o->text, "e.g. \"deliver the green book from the librarian to Anna by 10:30\"")->required();
  cmd->add_option("--id", o->id, "Command id (default: a fresh one); resending an id gets the same reply")
      ->check(CLI::Validator([](std::string& v) { return v.size() <= 128 ? "" : "at most 128 bytes"; }, "ID"));
  cmd->add_option("-t,--timeout", o->timeout_s, "Seconds to wait for the reply")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  cmd->footer("Grammar: docs/courier-language.md. Exit codes: 0 accepted; 1 rejected or no reply; 130 Ctrl-C.");
  return {cmd, [o](Context& ctx) {
            msg::CourierCommand c;
            c.kind = msg::CourierCommandKind::Text;
            c.text = o->text;
            return send_and_wait(*o, c, ctx);
          }};
}

Command add_courier_cancel(CLI::App& courier) {
  auto o = std::make_shared<CommandOptions>();
  auto* cmd = courier.add_subcommand("cancel", "Cancel a job (an object aboard is returned first)");
  add_domain_option(cmd, o->domain);
  cmd->add_option("job", o->job, "Job id, e.g. job-3")->required();
  cmd->add_option("--id", o->id, "Command id (default: a fresh one)")
      ->check(CLI::Validator([](std::string& v) { return v.size() <= 128 ? "" : "at most 128 bytes"; }, "ID"));
  cmd->add_option("-t,--timeout", o->timeout_s, "Seconds to wait for the reply")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  return {cmd, [o](Context& ctx) {
            msg::CourierCommand c;
            c.kind = msg::CourierCommandKind::Cancel;
            c.job_id = o->job;
            return send_and_wait(*o, c, ctx);
          }};
}

Command add_courier_jobs(CLI::App& courier) {
  auto o = std::make_shared<CommandOptions>();
  o->timeout_s = 1.0;
  auto* cmd = courier.add_subcommand("jobs", "Every job's latest state: queued, underway, opportunistic, ...");
  add_domain_option(cmd, o->domain);
  cmd->add_option("-t,--timeout", o->timeout_s, "Seconds to collect job states")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  return {cmd, [o](Context& ctx) { return list_jobs(*o, ctx); }};
}

}  // namespace autonomy::tools
