#pragma once
// Where courier commands are answered: checks each command (lengths, ids, repeats), interprets it
// (restricted English or the structured fields) against the office knowledge, journals the job it
// creates and the reply, and only then hands the job to the executive. Every command gets exactly
// one reply; a repeated command_id gets the journalled reply again, also after a restart.
// Plain C++ over the message value types: unit-tested without DDS.
#include "common/msg/courier.hpp"
#include "services/courier/core/execution/courier_executive.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/language/command_answer.hpp"
#include "services/courier/journal/journal.hpp"

#include <string>

namespace autonomy::courier {

class CommandDesk {
 public:
  // jobs_created: how many jobs the journal already holds (job ids go on from there).
  CommandDesk(const OfficeKnowledge& knowledge, CourierExecutive& executive, Journal& journal, int jobs_created);

  // now_sim_s: simulated time (the language's deadlines are relative to it).
  msg::CourierReply handle(const msg::CourierCommand& command, double now_sim_s, int64_t tick);

 private:
  // The office knowledge with every object where the courier's jobs believe it is.
  OfficeKnowledge believed_knowledge() const;
  msg::CourierReply deliver(const msg::CourierCommand& c, double now_sim_s);
  msg::CourierReply revise(const msg::CourierCommand& c, double now_sim_s);
  msg::CourierReply accept_delivery(const msg::CourierCommand& c, const Interpretation& i, double now_sim_s);
  msg::CourierReply apply_revision(const msg::CourierCommand& c, const Revision& r, double now_sim_s);

  const OfficeKnowledge& knowledge_;
  CourierExecutive& executive_;
  Journal& journal_;
  int jobs_created_;
};

// The reply as JSON text (the journal's copy) and back; parse errors give a rejected reply that
// says so.
std::string reply_to_json(const msg::CourierReply& reply);
msg::CourierReply reply_from_json(const std::string& text, const std::string& command_id);

}  // namespace autonomy::courier
