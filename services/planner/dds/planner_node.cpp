#include "planner_node.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>

#include "common/msg/text_limits.hpp"

namespace autonomy::planner {

PlannerNode::PlannerNode(service::Service& service, PlannerNodeOptions options)
    : options_(std::move(options)),
      request_topic_(service.participant(), dds::topics::planner_request),
      reply_topic_(service.participant(), dds::topics::planner_reply),
      progress_topic_(service.participant(), dds::topics::planner_progress),
      cancel_topic_(service.participant(), dds::topics::planner_cancel),
      plan_topic_(service.participant(), dds::topics::planner_plan),
      request_reader_(service.participant(), request_topic_),
      cancel_reader_(service.participant(), cancel_topic_),
      reply_writer_(service.participant(), reply_topic_),
      progress_writer_(service.participant(), progress_topic_),
      plan_writer_(service.participant(), plan_topic_),
      outbox_ready_(service.participant()) {
  auto& loop = service.loop();
  loop.on_samples<msg::PlanningRequest>(request_reader_,
                                        [this](auto samples) { on_requests(std::move(samples)); });
  loop.on_samples<msg::PlanningCancel>(cancel_reader_,
                                       [this](auto samples) { on_cancels(std::move(samples)); });
  loop.on_condition(outbox_ready_.handle(), [this] { on_worker_output(); });
  loop.every(std::chrono::milliseconds(20), [this] { enforce_deadlines(); });
  options_.workers = std::max<std::size_t>(1, options_.workers);
  for (std::size_t i = 0; i < options_.workers; ++i) {
    workers_.push_back(std::make_unique<Worker>());
    Worker& w = *workers_.back();
    w.thread = std::thread([this, &w] { work(w); });
  }
  spdlog::info(
      "planning requests on {}; default budget {} ms, at most {} ms; {} workers, up to {} "
      "waiting requests",
      dds::topics::planner_request.name, options_.default_budget_ms, options_.limits.max_budget_ms,
      options_.workers, options_.max_queue);
  service.set_ready();
}

PlannerNode::~PlannerNode() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    for (auto& w : workers_) w->cancel = true;
  }
  wake_.notify_all();
  for (auto& w : workers_)
    if (w->thread.joinable()) w->thread.join();
  // The loop has stopped: answer here what the worker finished (its search was cancelled) and
  // what still waited, so that no requester waits for a reply that never comes.
  try {
    std::vector<Outgoing> items;
    items.swap(outbox_);
    for (const Outgoing& item : items)
      if (const auto* r = std::get_if<msg::PlanningReply>(&item)) reply_writer_.write(*r);
    for (const Queued& q : queue_)
      reply_writer_.write(rejected_reply(q.request, "stopping",
                                         "the planner stopped before it started this request"));
  } catch (const std::exception& e) {
    spdlog::warn("stopping: the last replies were not sent: {}", e.what());
  }
}

void PlannerNode::on_requests(std::vector<dds::Sample<msg::PlanningRequest>> samples) {
  for (auto& s : samples) {
    if (!s.valid) continue;
    msg::PlanningRequest& q = s.value;
    const std::string shown = msg::clipped_for_log(q.request_id);
    if (auto it = answered_.find(q.request_id); it != answered_.end()) {
      spdlog::info("request {} repeated: the same reply again", shown);
      reply_writer_.write(it->second);
      continue;
    }
    if (pending_.count(q.request_id)) {
      spdlog::info("request {} repeated while it is queued or running: answered once, when done",
                   shown);
      continue;
    }
    if (auto rejected = check_request(q, options_.limits)) {
      spdlog::warn("request {} rejected: {}: {}", shown, rejected->reason,
                   msg::clipped_for_log(rejected->detail, 200));
      answer(*rejected, true);
      continue;
    }
    const std::size_t waiting =
        pending_.size() > options_.workers ? pending_.size() - options_.workers : 0;
    if (waiting >= options_.max_queue && pending_.size() >= options_.workers) {
      spdlog::warn("request {} answered busy: {} requests wait already", shown, waiting);
      answer(rejected_reply(q, "busy",
                            "the planner is busy: " + std::to_string(waiting) +
                                " requests wait already; send it again later"),
             false);
      continue;
    }
    spdlog::info("request {} from {}: engine {}, budget {} ms{}", shown,
                 msg::clipped_for_log(q.requester), q.engine.empty() ? "chronological" : q.engine,
                 q.budget_ms > 0 ? q.budget_ms : options_.default_budget_ms,
                 pending_.empty() ? "" : ", " + std::to_string(pending_.size()) + " pending");
    pending_.insert(q.request_id);
    {
      const auto now = Clock::now();
      const auto budget =
          std::chrono::milliseconds(q.budget_ms > 0 ? q.budget_ms : options_.default_budget_ms);
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.push_back({std::move(q), now, now + budget});
    }
    wake_.notify_one();
  }
}

void PlannerNode::on_cancels(std::vector<dds::Sample<msg::PlanningCancel>> samples) {
  for (const auto& s : samples) {
    if (!s.valid) continue;
    const std::string& id = s.value.request_id;
    const std::string shown = msg::clipped_for_log(id);
    if (!pending_.count(id)) {
      if (answered_.count(id))
        spdlog::info("cancel of {}: already answered", shown);
      else
        spdlog::warn("cancel of {}: no such request", shown);
      continue;
    }
    std::optional<msg::PlanningRequest> dequeued;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      bool running = false;
      for (auto& w : workers_) {
        if (w->running == id) {
          w->cancel = true;
          running = true;
        }
      }
      for (auto it = queue_.begin(); !running && it != queue_.end(); ++it) {
        if (it->request.request_id == id) {
          dequeued = std::move(it->request);
          queue_.erase(it);
          break;
        }
      }
    }
    if (dequeued) {
      spdlog::info("cancel of {}: taken out of the queue", shown);
      msg::PlanningReply r = rejected_reply(*dequeued, "", "cancelled before it started");
      r.status = msg::PlanningStatus::Cancelled;
      r.request_id = dequeued->request_id;
      answer(r, true);
    } else {
      spdlog::info("cancel of {}: stopping its search", shown);
    }
  }
}

void PlannerNode::on_worker_output() {
  outbox_ready_.reset();  // before taking: a post after this triggers it again
  std::vector<Outgoing> items;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    items.swap(outbox_);
  }
  for (const Outgoing& item : items) {
    if (const auto* p = std::get_if<msg::PlanningProgress>(&item)) {
      if (pending_.count(p->request_id)) progress_writer_.write(*p);
      continue;
    }
    const auto& reply = std::get<msg::PlanningReply>(item);
    if (!pending_.count(reply.request_id)) {  // the watchdog answered it already
      spdlog::warn("request {}: a late result ({}) dropped: it was answered at its deadline",
                   msg::clipped_for_log(reply.request_id), msg::to_string(reply.status));
      continue;
    }
    answer(reply, true);
  }
}

msg::PlanningReply PlannerNode::out_of_time_reply(const msg::PlanningRequest& q,
                                                  const std::string& detail) {
  msg::PlanningReply r = rejected_reply(q, "", detail);
  r.status = msg::PlanningStatus::OutOfTime;
  r.request_id = q.request_id;
  return r;
}

void PlannerNode::enforce_deadlines() {
  const auto now = Clock::now();
  const auto margin = std::chrono::milliseconds(options_.margin_ms);
  std::vector<msg::PlanningReply> late;
  if (last_watch_ != Clock::time_point{} && now - last_watch_ > margin) running_grace_until_ = now + margin;
  last_watch_ = now;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (auto it = queue_.begin(); it != queue_.end();) {
      if (now < it->deadline) {
        ++it;
        continue;
      }
      const double waited = std::chrono::duration<double, std::milli>(now - it->received).count();
      late.push_back(out_of_time_reply(
          it->request, "the time budget ended while the request waited for a worker (every one "
                       "was busy)"));
      late.back().statistics.elapsed_ms = waited;
      it = queue_.erase(it);
    }
    for (auto& w : workers_) {
      if (w->running.empty() || now < std::max(w->deadline + margin, running_grace_until_) ||
          !pending_.count(w->running))
        continue;
      // A stage that did not honour the budget: the requester is answered now, the search is
      // told to stop, and what it returns later is dropped.
      w->cancel = true;
      msg::PlanningRequest q;
      q.request_id = w->running;
      late.push_back(out_of_time_reply(
          q, "the time budget ended and the search had not stopped " +
                 std::to_string(options_.margin_ms) + " ms later; it was cancelled"));
    }
  }
  for (const msg::PlanningReply& r : late) {
    spdlog::warn("request {}: {}", msg::clipped_for_log(r.request_id), r.detail);
    answer(r, true);
  }
}

void PlannerNode::answer(const msg::PlanningReply& reply, bool remember) {
  pending_.erase(reply.request_id);
  if (remember && !answered_.count(reply.request_id)) {
    answered_[reply.request_id] = reply;
    answered_order_.push_back(reply.request_id);
    while (answered_order_.size() > options_.remembered_replies) {
      answered_.erase(answered_order_.front());
      answered_order_.pop_front();
    }
  }
  reply_writer_.write(reply);
  if (reply.status != msg::PlanningStatus::Rejected) {
    spdlog::info(
        "request {}: {}{}, {} decisions, {} backtracks, {:.1f} ms{}",
        msg::clipped_for_log(reply.request_id), msg::to_string(reply.status),
        reply.has_plan ? ", makespan " + std::to_string(reply.plan.makespan) : std::string(),
        reply.statistics.decisions, reply.statistics.backtracks, reply.statistics.elapsed_ms,
        reply.violations.empty() ? "" : ", INVALID plan: " + reply.violations.front());
  }
  if (reply.has_plan && reply.violations.empty())
    plan_writer_.write({reply.requester, reply.request_id, reply.status, reply.engine,
                        reply.plan_origin, reply.plan});
}

void PlannerNode::post(Outgoing item) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    outbox_.push_back(std::move(item));
  }
  outbox_ready_.trigger();
}

void PlannerNode::work(Worker& self) {
  for (;;) {
    Queued q;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      q = std::move(queue_.front());
      queue_.pop_front();
      self.running = q.request.request_id;
      self.deadline = q.deadline;
      self.cancel = false;
    }
    msg::PlanningReply reply;
    try {
      reply = plan_one(q, self);
    } catch (const std::exception& e) {
      // Nothing a request holds should get here; if it does, it is answered, not fatal.
      spdlog::error("request {}: planning failed: {}", msg::clipped_for_log(q.request.request_id),
                    e.what());
      reply = rejected_reply(q.request, "internal_error", e.what());
    }
    if (stopping_ && reply.status == msg::PlanningStatus::Cancelled)
      reply.detail = "the planner is stopping";
    {
      std::lock_guard<std::mutex> lock(mutex_);
      self.running.clear();
    }
    post(std::move(reply));  // when stopping, the destructor sends it
  }
}

msg::PlanningReply PlannerNode::plan_one(const Queued& queued, Worker& self) {
  const msg::PlanningRequest& q = queued.request;
  const auto received = queued.received, deadline = queued.deadline;
  const auto elapsed_ms = [received] {
    return std::chrono::duration<double, std::milli>(Clock::now() - received).count();
  };
  auto prepared = prepare_run(q);
  if (auto* rejected = std::get_if<msg::PlanningReply>(&prepared)) {
    spdlog::warn("request {} rejected: {}: {}", msg::clipped_for_log(q.request_id),
                 rejected->reason, msg::clipped_for_log(rejected->detail, 200));
    return std::move(*rejected);
  }
  RunControl control;
  control.cancelled = [&self] { return self.cancel.load(std::memory_order_relaxed); };
  control.out_of_time = [deadline] { return Clock::now() >= deadline; };
  control.elapsed_ms = elapsed_ms;
  control.on_progress = [this](const msg::PlanningProgress& p) { post(p); };
  return run_planning(q, std::get<PreparedRun>(prepared), control);
}

}  // namespace autonomy::planner
