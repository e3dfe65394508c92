#pragma once
// The executive's side of the planner (autonomy/planner/request and reply): one request at a
// time, each with a fresh id; a reply for any other id is stale and dropped. The node decides
// when to ask again (a planner that died mid-request never answers: the executive retries, it
// never waits for ever).
#include <chrono>
#include <optional>
#include <string>

#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/dds/writer.hpp"

namespace autonomy::executive {

class PlannerLink {
 public:
  using Clock = std::chrono::steady_clock;

  PlannerLink(const dds::Participant& participant, std::string requester);

  // Sends `request` under a new id (requester filled in); any earlier one is forgotten.
  std::string ask(msg::PlanningRequest request, const std::string& purpose);
  // The reply to the request outstanding, once; stale replies are dropped.
  std::optional<msg::PlanningReply> take_reply();
  // Forgets the outstanding request (its reply, if one ever comes, is then stale).
  void forget() { outstanding_.reset(); }
  // Asks the planner to end the outstanding request's search (so that requests asked again
  // do not queue up behind it).
  void cancel();

  bool waiting() const { return outstanding_.has_value(); }
  const std::string& outstanding_id() const { return outstanding_->id; }
  std::int64_t outstanding_origin() const { return outstanding_->origin; }
  Clock::duration waited() const { return Clock::now() - outstanding_->sent; }
  std::size_t planners() const { return request_writer_.matched_readers(); }
  const dds::Reader<msg::PlanningReply>& reply_reader() const { return reply_reader_; }

 private:
  struct Outstanding {
    std::string id;
    std::int64_t origin = 0;
    Clock::time_point sent;
  };
  std::string requester_;
  dds::Topic<msg::PlanningRequest> request_topic_;
  dds::Topic<msg::PlanningReply> reply_topic_;
  dds::Topic<msg::PlanningCancel> cancel_topic_;
  dds::Writer<msg::PlanningRequest> request_writer_;
  dds::Writer<msg::PlanningCancel> cancel_writer_;
  dds::Reader<msg::PlanningReply> reply_reader_;
  std::optional<Outstanding> outstanding_;
  std::uint64_t next_ = 1;
};

}  // namespace autonomy::executive
