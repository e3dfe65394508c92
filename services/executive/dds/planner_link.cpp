#include "planner_link.hpp"

#include <spdlog/spdlog.h>

namespace autonomy::executive {

PlannerLink::PlannerLink(const dds::Participant& participant, std::string requester)
    : requester_(std::move(requester)),
      request_topic_(participant, dds::topics::planner_request),
      reply_topic_(participant, dds::topics::planner_reply),
      cancel_topic_(participant, dds::topics::planner_cancel),
      request_writer_(participant, request_topic_),
      cancel_writer_(participant, cancel_topic_),
      reply_reader_(participant, reply_topic_) {}

std::string PlannerLink::ask(msg::PlanningRequest request, const std::string& purpose) {
  request.requester = requester_;
  // The wall clock in the id keeps ids unique across executive restarts (the planner answers a
  // repeated id with its remembered reply).
  const auto stamp = std::chrono::duration_cast<std::chrono::milliseconds>(
                         std::chrono::system_clock::now().time_since_epoch())
                         .count();
  request.request_id = requester_ + "-" + std::to_string(stamp) + "-" + std::to_string(next_++);
  outstanding_ = Outstanding{request.request_id, request.plan_origin, Clock::now()};
  spdlog::info("plan request {} ({}): origin {} s, {} planner(s) matched", request.request_id,
               purpose, request.plan_origin, request_writer_.matched_readers());
  request_writer_.write(request);
  return request.request_id;
}

void PlannerLink::cancel() {
  if (outstanding_) cancel_writer_.write({outstanding_->id, requester_});
}

std::optional<msg::PlanningReply> PlannerLink::take_reply() {
  std::optional<msg::PlanningReply> found;
  for (auto& s : reply_reader_.take()) {
    if (!s.valid || s.value.requester != requester_) continue;
    if (!outstanding_ || s.value.request_id != outstanding_->id) continue;  // stale
    found = std::move(s.value);
  }
  if (found) outstanding_.reset();
  return found;
}

}  // namespace autonomy::executive
