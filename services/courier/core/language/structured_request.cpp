#include "services/courier/core/language/structured_request.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/language/delivery_completion.hpp"

#include <cmath>

namespace autonomy::courier {

namespace {

Located field(const char* name, const std::string& value) {
  return {value, 0, name};
}

// Rejects values no text command could carry either: overlong, control characters, not ASCII.
void check_field(const char* name, const std::string& value) {
  if (value.size() > kMaxFieldBytes)
    reject(RejectReason::too_long,
           std::string("field ") + name + " has " + std::to_string(value.size()) +
               " bytes; at most " + std::to_string(kMaxFieldBytes) + " are read",
           field(name, value.substr(0, 16)));
  for (unsigned char c : value)
    if (c < 0x20 || c >= 0x7f)
      reject(RejectReason::bad_character,
             std::string("field ") + name + " has a control character or a byte that is not ASCII",
             field(name, ""));
}

Interpretation interpret(const StructuredRequest& r, const OfficeKnowledge& k, double now) {
  check_field("object_id", r.object_id);
  check_field("kind", r.kind);
  check_field("colour", r.colour);
  check_field("from", r.from);
  check_field("to", r.to);
  check_field("deadline", r.deadline);

  DeliveryDraft d;
  d.end = field("to", r.to);
  d.missing_pickup = field("from", r.from);
  d.object = {lower_case(r.kind), lower_case(r.colour), r.object_id};
  d.object_at = r.object_id.empty() ? field("kind", r.kind) : field("object_id", r.object_id);
  if (r.object_id.empty() && r.kind.empty())
    reject(RejectReason::missing_object, "give object_id, or kind (and colour)",
           field("kind", r.kind));
  if (!r.kind.empty()) {
    const auto kinds = object_kind_words(k);
    if (!is_word_in(r.kind, kinds)) {
      const auto close = closest_names(r.kind, kinds);
      reject(RejectReason::unknown_object,
             "no object kind '" + r.kind + "' is known" +
                 (close.empty() ? "" : "; " + did_you_mean(close)),
             field("kind", r.kind), close);
    }
  }
  if (!r.colour.empty()) {
    const auto colours = colour_words(k);
    if (!is_word_in(r.colour, colours)) {
      const auto close = closest_names(r.colour, colours);
      reject(
          RejectReason::unknown_colour,
          "'" + r.colour + "' is not a colour" + (close.empty() ? "" : "; " + did_you_mean(close)),
          field("colour", r.colour), close);
    }
  }
  if (!r.from.empty()) d.pickup = name_ref(k, r.from, field("from", r.from));
  if (!r.to.empty()) d.delivery = name_ref(k, r.to, field("to", r.to));

  if (!r.deadline.empty() && r.deadline_s)
    reject(RejectReason::repeated_phrase, "give deadline or deadline_s, not both",
           field("deadline", r.deadline));
  if (!r.deadline.empty()) {
    const auto s = parse_clock(r.deadline);
    if (!s)
      reject(RejectReason::bad_time, "'" + r.deadline + "' is not a time of day HH:MM",
             field("deadline", r.deadline));
    d.deadline_s = *s;
    check_deadline(*s, now, field("deadline", r.deadline));
  } else if (r.deadline_s) {
    const Located at =
        field("deadline_s", std::isfinite(*r.deadline_s) ? format_clock(*r.deadline_s) : "");
    if (!std::isfinite(*r.deadline_s) || *r.deadline_s < 0.0)
      reject(RejectReason::bad_time, "deadline_s is not a number of seconds of the day", at);
    d.deadline_s = *r.deadline_s;
    check_deadline(*r.deadline_s, now, at);
  }
  return complete_delivery(d, k);
}

}  // namespace

CommandAnswer interpret_request(const StructuredRequest& request, const OfficeKnowledge& knowledge,
                                double now_sim_s) {
  CommandAnswer answer;
  try {
    answer.delivery = interpret(request, knowledge, knowledge.clock.time_of_day(now_sim_s));
    answer.kind = CommandAnswer::Kind::delivery;
  } catch (const RejectionError& e) {
    answer = CommandAnswer{};
    answer.rejection = e.rejection;
  }
  return answer;
}

}  // namespace autonomy::courier
