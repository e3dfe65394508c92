#pragma once
// Maximum lengths of the strings in DDS samples. IDL strings are unbounded on the wire (bounded
// strings would make an overlong write fail at the sender, where nobody sees why), so every
// service checks what it receives against these limits and rejects a sample with a longer field
// on its usual status or rejection topic, saying which field and how long it was. Logs never
// print a received string whole: clipped_for_log() cuts it.
//
// The limits are part of the topic catalogue (docs/topics.md, "String limits").
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>

namespace autonomy::msg {

// Identifiers chosen by senders: goal, request, job, command and message ids.
inline constexpr std::size_t kMaxIdLength = 128;
// Names of things in the world or in a set: robots, participants, doors, places, people, objects,
// layers, sources of commands.
inline constexpr std::size_t kMaxNameLength = 64;
// Free text meant for people: reasons, details, courier commands, team message payloads.
inline constexpr std::size_t kMaxTextLength = 1024;
// Documents sent inside a sample: planner models and problems (text or serialized protobuf).
inline constexpr std::size_t kMaxDocumentLength = 1 << 20;

// "goal_id has 100000 bytes, more than 128" when `value` is longer than `max`, else nothing.
std::optional<std::string> length_problem(const char* field, const std::string& value, std::size_t max);

// One string field of a sample and its limit, for first_length_problem().
struct FieldLimit {
  const char* field;
  const std::string& value;
  std::size_t max;
};

// The length_problem() of the first field over its limit, in the order given, or nothing.
std::optional<std::string> first_length_problem(std::initializer_list<FieldLimit> fields);

// `value` as a log may show it: at most `keep` bytes, then "...(N bytes)" when it was longer.
std::string clipped_for_log(const std::string& value, std::size_t keep = 48);

// At most `max` bytes of `value`: an overlong id echoed in a rejection, so that the sender can
// still tell which of its requests it was without the service repeating megabytes.
std::string clipped_id(const std::string& value, std::size_t max = kMaxIdLength);

}  // namespace autonomy::msg
