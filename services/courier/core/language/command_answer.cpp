#include "services/courier/core/language/command_answer.hpp"

#include "services/courier/core/knowledge/day_clock.hpp"

namespace autonomy::courier {

const char* to_string(RejectReason reason) {
  switch (reason) {
    case RejectReason::empty_command:
      return "empty_command";
    case RejectReason::too_long:
      return "too_long";
    case RejectReason::bad_character:
      return "bad_character";
    case RejectReason::unknown_verb:
      return "unknown_verb";
    case RejectReason::unexpected_word:
      return "unexpected_word";
    case RejectReason::missing_object:
      return "missing_object";
    case RejectReason::unknown_object:
      return "unknown_object";
    case RejectReason::unknown_colour:
      return "unknown_colour";
    case RejectReason::missing_place:
      return "missing_place";
    case RejectReason::unknown_place:
      return "unknown_place";
    case RejectReason::unknown_person:
      return "unknown_person";
    case RejectReason::unknown_room:
      return "unknown_room";
    case RejectReason::place_not_in_room:
      return "place_not_in_room";
    case RejectReason::ambiguous_place:
      return "ambiguous_place";
    case RejectReason::ambiguous_person:
      return "ambiguous_person";
    case RejectReason::ambiguous_object:
      return "ambiguous_object";
    case RejectReason::object_elsewhere:
      return "object_elsewhere";
    case RejectReason::object_aboard:
      return "object_aboard";
    case RejectReason::missing_pickup:
      return "missing_pickup";
    case RejectReason::missing_destination:
      return "missing_destination";
    case RejectReason::same_place:
      return "same_place";
    case RejectReason::bad_time:
      return "bad_time";
    case RejectReason::deadline_in_past:
      return "deadline_in_past";
    case RejectReason::deadline_after_midnight:
      return "deadline_after_midnight";
    case RejectReason::repeated_phrase:
      return "repeated_phrase";
    case RejectReason::missing_job:
      return "missing_job";
  }
  return "unknown";
}

std::string CommandAnswer::summary() const {
  switch (kind) {
    case Kind::delivery: {
      const Interpretation& d = delivery;
      std::string s =
          "deliver the " + (d.object.colour.empty() ? "" : d.object.colour + " ") + d.object.kind;
      if (!d.object.id.empty()) s += " (" + d.object.id + ")";
      s += " from " + d.pickup_place + " to " + d.delivery_place;
      if (d.deadline_s) s += " by " + format_clock(*d.deadline_s);
      return s;
    }
    case Kind::revision: {
      const Revision& r = revision;
      if (r.kind == Revision::Kind::cancel) return "cancel job " + r.job;
      std::string s = "change job " + r.job + ":";
      if (!r.delivery_place.empty()) s += " destination " + r.delivery_place;
      if (r.deadline_s) s += " deadline " + format_clock(*r.deadline_s);
      return s;
    }
    case Kind::rejected:
      break;
  }
  std::string s = std::string("rejected (") + to_string(rejection.reason) + ")";
  if (!rejection.field.empty()) s += " in field " + rejection.field;
  if (rejection.column > 0) s += " at column " + std::to_string(rejection.column);
  return s + ": " + rejection.message;
}

}  // namespace autonomy::courier
