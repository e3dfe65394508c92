#pragma once
// What the text and the structured interpreters share, so that programs and people get identical
// answers: the meaning of a single name as a place (a place, a person's desk, a room's one place
// to hand things over), the vocabulary of object kinds and colours, deadline checks, and the
// completion of a delivery from knowledge (the object known to be at the pickup place, where a
// known object lies, the addressee, the most frequent destination learned so far).
//
// Problems are thrown as RejectionError and caught by the two interpreters, which turn them into
// a CommandAnswer; nothing thrown here escapes the library.
#include "services/courier/core/language/command_answer.hpp"

#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace autonomy::courier {

struct OfficeKnowledge;
struct Person;
struct Place;

// Where a part of a command came from, for rejections: a word and its column (text) or a field.
struct Located {
  std::string word;
  int column = 0;
  std::string field;
};

struct RejectionError : std::exception {
  Rejection rejection;
  explicit RejectionError(Rejection r) : rejection(std::move(r)) {}
  const char* what() const noexcept override { return rejection.message.c_str(); }
};

[[noreturn]] void reject(RejectReason reason, std::string message, const Located& at,
                         std::vector<std::string> suggestions = {});

// A place as the command means it, with the assumption made to find it (empty when it was named).
struct PlaceRef {
  std::string place;       // place name in the knowledge
  std::string person;      // the person named, or whose desk `place` is; may be empty
  std::string assumption;  // "Wolfram's desk (a118-desk)", "room A-114 means Anna's desk (...)"
  Located at;
};

// "Michael", "the librarian": how a person is written in replies.
std::string person_phrase(const Person& person);

// A place that is not a room, with the person sitting there.
PlaceRef place_ref(const OfficeKnowledge& knowledge, const Place& place, const Located& at);
// A person as a place: their desk.
PlaceRef person_ref(const OfficeKnowledge& knowledge, const Person& person, const Located& at);
// A room as a place: the one person's desk in it, else its one loading station, else its only
// place; rejects rooms with none or several of them.
PlaceRef room_ref(const OfficeKnowledge& knowledge, const Place& room, const Located& at);
// A single name (place, alias, room, person, role) as a place; rejects unknown names with
// suggestions and roles held by several people.
PlaceRef name_ref(const OfficeKnowledge& knowledge, const std::string& name, const Located& at);

// The words the language knows as object kinds and colours: the knowledge's plus common ones.
std::vector<std::string> object_kind_words(const OfficeKnowledge& knowledge);
std::vector<std::string> colour_words(const OfficeKnowledge& knowledge);
bool is_word_in(std::string_view word, const std::vector<std::string>& words);

// Checks a deadline in seconds of the day against now (seconds of the day): rejects deadlines
// not after now and beyond 24:00.
void check_deadline(double deadline_s, double now_of_day_s, const Located& at);

struct DeliveryDraft {
  ObjectDescription object;  // kind and colour lower-case; id as given (checked here)
  Located object_at;
  std::optional<PlaceRef> pickup;
  std::optional<PlaceRef> delivery;
  std::optional<double> deadline_s;  // already checked with check_deadline
  Located end;                       // where a missing destination is reported
  Located missing_pickup;            // where a missing pickup is reported (text: the end, too)
};

// Completes the draft from knowledge or rejects it saying what is missing.
Interpretation complete_delivery(const DeliveryDraft& draft, const OfficeKnowledge& knowledge);

}  // namespace autonomy::courier
