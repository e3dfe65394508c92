#pragma once
// The planner's thin DDS shell. Requests (autonomy/planner/request) are checked on the event
// loop; good ones go into a FIFO queue that `workers` threads plan from, one request each
// (beyond max_queue waiting ones a request is answered `busy` at once and may be sent again).
// A request's budget counts from its arrival: its deadline holds in the queue too (a request
// still waiting at its deadline is answered out_of_time by the loop's watchdog), and a running
// one not answered by deadline + margin is answered out_of_time by the watchdog, so one request
// never holds up another beyond its own budget. The worker's termination condition carries the
// deadline and the cancellation (autonomy/planner/cancel), so a cancelled or timed-out search
// ends with the best plan so far. The worker never touches a DDS writer: it hands its
// progress events and replies to the loop through a mutex-guarded outbox and a guard condition;
// no lock is held across a DDS call. Every request gets exactly one reply; a repeated request_id
// gets the remembered reply again (one still queued or running is answered once, when done).
// Valid plans become the requester's latest plan (autonomy/planner/plan, state). On stop, the
// running search is cancelled and answered (best plan so far), waiting requests are rejected
// (`stopping`).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/waitset.hpp"
#include "common/dds/writer.hpp"
#include "common/service/service.hpp"
#include "planning_request.hpp"

namespace autonomy::planner {

struct PlannerNodeOptions {
  std::int64_t default_budget_ms = 10000;  // for requests with budget_ms 0
  RequestLimits limits;
  std::size_t max_queue = 8;              // waiting requests besides the running ones
  std::size_t remembered_replies = 1000;  // for repeated request ids
  std::size_t workers = 2;                // searches at once, each on its own thread
  // A running request not answered by its deadline plus this is answered out_of_time by the
  // loop (its search is cancelled; a late result is dropped).
  std::int64_t margin_ms = 500;
};

class PlannerNode {
 public:
  PlannerNode(service::Service& service, PlannerNodeOptions options);
  ~PlannerNode();
  PlannerNode(const PlannerNode&) = delete;
  PlannerNode& operator=(const PlannerNode&) = delete;

 private:
  using Outgoing = std::variant<msg::PlanningProgress, msg::PlanningReply>;

  void on_requests(std::vector<dds::Sample<msg::PlanningRequest>> samples);
  void on_cancels(std::vector<dds::Sample<msg::PlanningCancel>> samples);
  void on_worker_output();
  // Loop thread: writes the reply (and the latest plan); remember: answer a repeat with it.
  void answer(const msg::PlanningReply& reply, bool remember);
  using Clock = std::chrono::steady_clock;
  struct Queued {
    msg::PlanningRequest request;
    Clock::time_point received, deadline;
  };
  struct Worker {
    std::thread thread;
    std::string running;  // request id, empty when idle (under mutex_)
    Clock::time_point deadline;
    std::atomic<bool> cancel{false};
  };
  void work(Worker& self);  // a worker thread
  msg::PlanningReply plan_one(const Queued& request, Worker& self);
  // Loop thread: answers what waited or ran past its deadline (see the class comment).
  void enforce_deadlines();
  // When the watchdog last ran, and until when running searches get their margin again: a gap
  // above the margin means this process did not run (SIGSTOP, starved), not that a search ignored
  // its budget; the search answers with its best plan once it runs again.
  Clock::time_point last_watch_{};
  Clock::time_point running_grace_until_{};
  msg::PlanningReply out_of_time_reply(const msg::PlanningRequest& q, const std::string& detail);
  void post(Outgoing item);  // worker -> loop

  PlannerNodeOptions options_;

  dds::Topic<msg::PlanningRequest> request_topic_;
  dds::Topic<msg::PlanningReply> reply_topic_;
  dds::Topic<msg::PlanningProgress> progress_topic_;
  dds::Topic<msg::PlanningCancel> cancel_topic_;
  dds::Topic<msg::LatestPlan> plan_topic_;
  dds::Reader<msg::PlanningRequest> request_reader_;
  dds::Reader<msg::PlanningCancel> cancel_reader_;
  dds::Writer<msg::PlanningReply> reply_writer_;
  dds::Writer<msg::PlanningProgress> progress_writer_;
  dds::Writer<msg::LatestPlan> plan_writer_;
  dds::GuardCondition outbox_ready_;

  // Loop thread only.
  std::map<std::string, msg::PlanningReply> answered_;
  std::deque<std::string> answered_order_;  // oldest first, for forgetting
  std::set<std::string> pending_;           // queued or running

  // Shared with the worker, under mutex_ (cancel_ and stopping_ are also read without it by
  // the search's termination condition).
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Queued> queue_;
  std::vector<Outgoing> outbox_;
  std::atomic<bool> stopping_{false};

  std::vector<std::unique_ptr<Worker>> workers_;  // last: start when everything above exists
};

}  // namespace autonomy::planner
