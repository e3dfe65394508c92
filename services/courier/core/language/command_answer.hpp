#pragma once
// The courier's answer to one command, text or structured: an accepted delivery with its
// interpretation (what, from where, to where, by when, and what was assumed to complete it), an
// accepted revision of a job, or a rejection saying why and where. docs/courier-language.md lists
// every reason with an example.
#include <optional>
#include <string>
#include <vector>

namespace autonomy::courier {

struct ObjectDescription {
  std::string kind;    // "letter"; lower-case
  std::string colour;  // "red"; lower-case; empty when not said and not known
  std::string id;      // the known object meant, when exactly one matches; else empty
};

// A delivery job as understood: every place is a place name of the office knowledge.
struct Interpretation {
  ObjectDescription object;
  std::string pickup_place;
  std::string delivery_place;
  std::string pickup_person;         // who hands it over (named, or whose desk it is); may be empty
  std::string delivery_person;       // who takes it; may be empty (a table, a station)
  std::optional<double> deadline_s;  // seconds of the day, after `now`
  // What was filled in from knowledge, in plain English, in the order it was decided, e.g.
  // "object: the letter known to be on Wolfram's desk (letter-4)".
  std::vector<std::string> assumptions;
};

// A change to a job already accepted ("cancel job J", "change the deadline of job J to 11:30").
// The language does not know which jobs exist: the caller checks `job` and, for text, reports an
// unknown job at `job_column`.
struct Revision {
  enum class Kind { cancel, change };
  Kind kind = Kind::cancel;
  std::string job;     // as written
  int job_column = 0;  // 1-based column of the job id in the text; 0 for structured requests
  // change: the new destination (place name empty when unchanged) and/or the new deadline.
  std::string delivery_place;
  std::string delivery_person;
  std::optional<double> deadline_s;
  std::vector<std::string> assumptions;
};

enum class RejectReason {
  empty_command,            // nothing but spaces and punctuation
  too_long,                 // longer than kMaxCommandBytes (text) or kMaxFieldBytes (a field)
  bad_character,            // a control character or a byte that is not ASCII
  unknown_verb,             // the first word starts no command
  unexpected_word,          // a word the grammar does not allow there
  missing_object,           // no object said ("deliver to Michael")
  unknown_object,           // an object kind or id the courier does not know
  unknown_colour,           // a word before the object kind that is not a colour
  missing_place,            // a preposition with no place after it ("deliver the book to")
  unknown_place,            // a place name nobody knows
  unknown_person,           // "Miachel's desk": a possessive that names nobody
  unknown_room,             // "in room A-122"
  place_not_in_room,        // "the desk in room A-111" when A-111 has no desk
  ambiguous_place,          // "the desk" (which one?), or a room with several places
  ambiguous_person,         // a role held by several people
  ambiguous_object,         // two objects fit the description at the pickup place
  object_elsewhere,         // the object named by id is known to be somewhere else
  object_aboard,            // the object named is aboard a robot already
  missing_pickup,           // nothing says or implies where the object is
  missing_destination,      // nothing says or implies where it goes
  same_place,               // pickup and destination are the same place
  bad_time,                 // "by 25:00", "within 20" (no unit)
  deadline_in_past,         // the deadline is not after now
  deadline_after_midnight,  // deadlines are times of the current day
  repeated_phrase,          // "from" (or "to", a deadline) said twice
  missing_job,              // a revision without a job id
};

const char* to_string(RejectReason reason);  // the enumerator's name, "unknown_place"

struct Rejection {
  RejectReason reason = RejectReason::unexpected_word;
  std::string message;  // one sentence: what is wrong, with the suggestions when there are any
  std::string word;     // the word at fault as written (text) or the field's value (structured)
  // Text: 1-based byte column of `word`; text length + 1 when something is missing at the end.
  // Structured requests: 0.
  int column = 0;
  std::string field;  // structured requests: the field at fault ("from", "deadline"); else empty
  std::vector<std::string> suggestions;  // known names close to an unknown one, or the candidates
};

struct CommandAnswer {
  enum class Kind { delivery, revision, rejected };
  Kind kind = Kind::rejected;
  Interpretation delivery;  // kind == delivery
  Revision revision;        // kind == revision
  Rejection rejection;      // kind == rejected

  bool accepted() const { return kind != Kind::rejected; }
  // One line for replies and logs: "deliver the red letter (letter-red) from meeting-table to
  // michael-desk by 10:30", "cancel job j3", "rejected (unknown_place) at column 40: ...".
  std::string summary() const;
};

}  // namespace autonomy::courier
