#include "services/courier/core/language/command_interpreter.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"
#include "services/courier/core/language/command_tokens.hpp"
#include "services/courier/core/language/delivery_completion.hpp"

#include <algorithm>
#include <initializer_list>
#include <utility>

namespace autonomy::courier {

namespace {

bool is_one_of(const std::string& word, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) { return word == w; });
}

bool is_article(const std::string& w) {
  return is_one_of(w, {"the", "a", "an", "this", "that"});
}
bool is_delivery_verb(const std::string& w) {
  return is_one_of(
      w, {"put", "place", "bring", "take", "deliver", "carry", "move", "send", "fetch", "get"});
}
bool is_deadline_word(const std::string& w) {
  return is_one_of(w, {"by", "before", "until", "till", "within"});
}
// Words that end an object or place phrase and start the next phrase.
bool is_phrase_start(const std::string& w) {
  return is_deadline_word(w) ||
         is_one_of(w, {"from", "to", "into", "onto", "on", "at", "for", "in", "and", "please"});
}
bool starts_with_digit(const std::string& w) {
  return !w.empty() && w[0] >= '0' && w[0] <= '9';
}
bool is_job_id(const std::string& w) {
  return !w.empty() && std::all_of(w.begin(), w.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
  });
}

const std::vector<std::string> kVerbs = {"put",   "place",  "bring", "take",  "deliver",
                                         "carry", "move",   "send",  "fetch", "get",
                                         "pick",  "cancel", "change"};

std::string joined(const std::vector<Token>& tokens, std::size_t from, std::size_t to, char sep) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) {
    if (i > from && sep != 0) out += sep;
    out += tokens[i].word;
  }
  return out;
}

// The words as written, for messages.
std::string written(const std::vector<Token>& tokens, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) out += (i > from ? " " : "") + tokens[i].text;
  return out;
}

std::vector<std::string> names_of(const std::vector<const Place*>& places) {
  std::vector<std::string> names;
  for (const Place* p : places) names.push_back(p->name);
  return names;
}

// Whether `word` describes `place`: its kind, a synonym of it, or a part of one of its names
// ("meeting" and "table" both describe meeting-table).
bool describes(const std::string& word, const Place& place) {
  if (word == to_string(place.kind)) return true;
  if (place.kind == PlaceKind::station && is_one_of(word, {"tray", "loading"})) return true;
  auto in_name = [&](const std::string& name) {
    const std::string n = lower_case(name);
    std::size_t start = 0;
    while (start <= n.size()) {
      std::size_t end = n.find_first_of("- ", start);
      if (end == std::string::npos) end = n.size();
      if (n.compare(start, end - start, word) == 0) return true;
      start = end + 1;
    }
    return false;
  };
  if (in_name(place.name)) return true;
  return std::any_of(place.aliases.begin(), place.aliases.end(), in_name);
}

class TextInterpreter {
 public:
  TextInterpreter(std::string_view text, const OfficeKnowledge& k, double now_of_day_s)
      : text_(text), k_(k), now_(now_of_day_s) {}

  CommandAnswer run() {
    t_ = tokenize_command(text_);
    if (!t_.empty() && t_.back().word == "please") t_.pop_back();
    if (!t_.empty() && t_.front().word == "please") i_ = 1;
    if (i_ >= t_.size())
      reject(RejectReason::empty_command, "the command has no words", {"", 1, ""});
    const Token& verb = t_[i_];
    if (verb.word == "cancel") return cancel();
    if (verb.word == "change") return change();
    if (verb.word == "pick") {
      ++i_;
      if (!next_is("up")) unexpected("'pick' is followed by 'up' ('pick up the letter from ...')");
      ++i_;
      return delivery(true);
    }
    if (is_delivery_verb(verb.word)) {
      const std::size_t after = i_ + 1 + (i_ + 1 < t_.size() && is_article(t_[i_ + 1].word));
      if (after < t_.size() && t_[after].word == "job") {
        i_ = after;
        return revise_by_verb();
      }
      ++i_;
      return delivery(false);
    }
    const auto close = closest_names(verb.word, kVerbs);
    reject(RejectReason::unknown_verb,
           "a command starts with put, bring, take, deliver, pick up, cancel or change, not '" +
               verb.text + "'" + (close.empty() ? "" : "; " + did_you_mean(close)),
           at(verb), close);
  }

 private:
  // ---- cursor --------------------------------------------------------------------------------
  bool done() const { return i_ >= t_.size(); }
  bool next_is(const char* w) const { return !done() && t_[i_].word == w; }
  Located at(const Token& t) const { return {t.text, t.column, ""}; }
  Located end() const { return {"", static_cast<int>(text_.size()) + 1, ""}; }
  Located here() const { return done() ? end() : at(t_[i_]); }
  void skip_article() {
    if (!done() && is_article(t_[i_].word)) ++i_;
  }
  [[noreturn]] void unexpected(const std::string& expected) const {
    if (done())
      reject(RejectReason::unexpected_word, "the command ends too early: " + expected, end());
    reject(RejectReason::unexpected_word, "unexpected '" + t_[i_].text + "': " + expected, here());
  }
  // "in" starts a deadline when a duration follows ("in 20 minutes"), else it names a room.
  bool in_starts_deadline(std::size_t at) const {
    if (at + 1 >= t_.size()) return false;
    const std::string& n = t_[at + 1].word;
    return starts_with_digit(n) || is_one_of(n, {"half", "an"}) ||
           (n == "a" && at + 2 < t_.size() && is_one_of(t_[at + 2].word, {"minute", "hour"}));
  }
  bool ends_phrase(std::size_t at) const {
    const std::string& w = t_[at].word;
    return is_phrase_start(w) && (w != "in" || in_starts_deadline(at));
  }

  // ---- revisions -----------------------------------------------------------------------------
  Token job_id() {
    skip_article();
    if (next_is("job")) ++i_;
    if (done() || !is_job_id(t_[i_].word) || is_phrase_start(t_[i_].word))
      reject(RejectReason::missing_job, "say which job, e.g. 'job j7'", here());
    return t_[i_++];
  }
  CommandAnswer revision_answer(Revision::Kind kind, const Token& job) {
    CommandAnswer a;
    a.kind = CommandAnswer::Kind::revision;
    a.revision.kind = kind;
    a.revision.job = job.text;
    a.revision.job_column = job.column;
    return a;
  }
  CommandAnswer cancel() {
    ++i_;
    const Token job = job_id();
    if (!done()) unexpected("nothing follows the job to cancel");
    return revision_answer(Revision::Kind::cancel, job);
  }
  void set_destination(Revision& r, const PlaceRef& ref) {
    r.delivery_place = ref.place;
    r.delivery_person = ref.person;
    if (!ref.assumption.empty()) r.assumptions.push_back("destination: " + ref.assumption);
  }
  CommandAnswer change() {
    ++i_;
    skip_article();
    const bool destination = next_is("destination");
    if (!destination && !next_is("deadline"))
      unexpected(
          "'change' is followed by 'the destination of job ...' or 'the deadline of job ...'");
    ++i_;
    if (!next_is("of") && !next_is("for")) unexpected("'of job ...' comes next");
    ++i_;
    const Token job = job_id();
    if (!next_is("to"))
      unexpected("'to' and the new " + std::string(destination ? "destination" : "deadline"));
    ++i_;
    CommandAnswer a = revision_answer(Revision::Kind::change, job);
    if (destination) {
      set_destination(a.revision, place_phrase());
    } else {
      a.revision.deadline_s = done() || !is_deadline_word(t_[i_].word) ? clock_value() : deadline();
    }
    if (!done())
      unexpected("nothing follows the new " +
                 std::string(destination ? "destination" : "deadline"));
    return a;
  }
  // "deliver job j7 to Michael by 11:30": a new destination and/or deadline.
  CommandAnswer revise_by_verb() {
    const Token job = job_id();  // the cursor is at "job"
    CommandAnswer a = revision_answer(Revision::Kind::change, job);
    bool has_destination = false;
    while (!done()) {
      const Token& w = t_[i_];
      if (is_one_of(w.word, {"to", "into", "onto", "for"})) {
        if (has_destination)
          reject(RejectReason::repeated_phrase, "the destination is said twice", at(w));
        ++i_;
        set_destination(a.revision, place_phrase());
        has_destination = true;
      } else if (is_deadline_word(w.word) || (w.word == "in" && in_starts_deadline(i_))) {
        if (a.revision.deadline_s)
          reject(RejectReason::repeated_phrase, "the deadline is said twice", at(w));
        a.revision.deadline_s = deadline();
      } else {
        unexpected("a job's new destination ('to ...') or deadline ('by ...')");
      }
    }
    if (!has_destination && !a.revision.deadline_s)
      reject(RejectReason::missing_destination,
             "say the job's new destination ('to ...') or deadline ('by ...')", end());
    return a;
  }

  // ---- deliveries ----------------------------------------------------------------------------
  CommandAnswer delivery(bool pick_up) {
    DeliveryDraft d;
    d.end = end();
    d.missing_pickup = end();
    object_phrase(d);
    std::vector<PlaceRef> located;  // "on ...", "at ...", "in room ..." phrases, in order
    std::optional<Located> deadline_at;
    while (!done()) {
      const Token& w = t_[i_];
      if (w.word == "from") {
        if (d.pickup)
          reject(RejectReason::repeated_phrase, "where to pick up is said twice", at(w));
        ++i_;
        d.pickup = place_phrase();
      } else if (is_one_of(w.word, {"to", "into", "onto", "for"})) {
        if (d.delivery)
          reject(RejectReason::repeated_phrase, "the destination is said twice", at(w));
        ++i_;
        d.delivery = place_phrase();
      } else if (is_deadline_word(w.word) || (w.word == "in" && in_starts_deadline(i_))) {
        if (d.deadline_s)
          reject(RejectReason::repeated_phrase, "the deadline is said twice", at(w));
        d.deadline_s = deadline();
      } else if (is_one_of(w.word, {"on", "at", "in"})) {
        if (located.size() == 2)
          reject(RejectReason::repeated_phrase, "a third place; say 'from' one place 'to' another",
                 at(w));
        if (w.word != "in") ++i_;  // "in room A-114" keeps "in" as the room qualifier
        located.push_back(place_phrase());
      } else if (w.word == "and") {
        ++i_;
        if (done() || !is_delivery_verb(t_[i_].word))
          unexpected("'and' is followed by 'deliver it' (or bring, take, put)");
        ++i_;
        if (next_is("it") || next_is("them")) ++i_;
      } else {
        unexpected("'from', 'to', 'on', a deadline ('by 10:30') or the end of the command");
      }
    }
    // Places given with "on"/"at": the paper's "put X on A on B" is from A to B; one alone is the
    // pickup when the destination is already said or the verb is "pick up", else the destination.
    if (located.size() == 2) {
      if (d.pickup)
        reject(RejectReason::repeated_phrase, "where to pick up is said twice", located[0].at);
      if (d.delivery)
        reject(RejectReason::repeated_phrase, "the destination is said twice", located[1].at);
      d.pickup = located[0];
      d.delivery = located[1];
    } else if (located.size() == 1) {
      const bool as_pickup = !d.pickup && (d.delivery || pick_up);
      auto& slot = as_pickup ? d.pickup : d.delivery;
      if (slot)
        reject(RejectReason::repeated_phrase, "a place too many; say 'from' one place 'to' another",
               located[0].at);
      slot = located[0];
    }
    CommandAnswer a;
    a.kind = CommandAnswer::Kind::delivery;
    a.delivery = complete_delivery(d, k_);
    return a;
  }

  // [article] [person's] [colour] kind | object-id
  void object_phrase(DeliveryDraft& d) {
    skip_article();
    std::size_t stop = i_;
    while (stop < t_.size() && !ends_phrase(stop) && t_[stop].word != "in") ++stop;
    if (stop == i_ || (stop == i_ + 1 && is_one_of(t_[i_].word, {"it", "them", "something"})))
      reject(RejectReason::missing_object, "say what to deliver, e.g. 'the red letter'",
             i_ < t_.size() ? at(t_[i_]) : end());
    if (t_[i_].possessive) {  // "Wolfram's letter": picked up from Wolfram
      d.pickup = person_by_possessive(t_[i_]);
      ++i_;
      if (i_ == stop)
        reject(RejectReason::missing_object, "say what to deliver after '" + t_[i_ - 1].text + "'",
               here());
    }
    const Token& noun = t_[stop - 1];
    d.object_at = at(t_[i_]);
    const std::vector<std::string> kinds = object_kind_words(k_);
    if (stop - i_ > 1 && k_.find_object(noun.word) != nullptr)
      unexpected_at(i_, "an object id stands alone ('deliver " + noun.text + " to ...')");
    if (stop - i_ == 1 && k_.find_object(noun.word) != nullptr) {
      d.object.id = k_.find_object(noun.word)->id;
    } else if (is_word_in(noun.word, kinds)) {
      d.object.kind = noun.word;
      if (stop - i_ > 2) {
        reject(RejectReason::unknown_colour,
               "one colour before the object, not '" + t_[i_].text + " " + t_[i_ + 1].text + "'",
               at(t_[i_]));
      }
      if (stop - i_ == 2) {
        const Token& colour = t_[i_];
        const std::vector<std::string> colours = colour_words(k_);
        if (!is_word_in(colour.word, colours)) {
          const auto close = closest_names(colour.word, colours);
          reject(RejectReason::unknown_colour,
                 "'" + colour.text + "' is not a colour" +
                     (close.empty() ? "" : "; " + did_you_mean(close)),
                 at(colour), close);
        }
        d.object.colour = colour.word;
      }
    } else {
      std::vector<std::string> names = kinds;
      for (const KnownObject& o : k_.objects) names.push_back(o.id);
      const auto close = closest_names(noun.word, names);
      reject(RejectReason::unknown_object,
             "no object '" + noun.text + "' is known" +
                 (close.empty() ? "" : "; " + did_you_mean(close)),
             at(noun), close);
    }
    i_ = stop;
  }

  PlaceRef person_by_possessive(const Token& t) {
    const NameMeaning m = lookup_name(k_, t.word);
    if (m.people.size() == 1) return person_ref(k_, *m.people[0], at(t));
    if (m.people.size() > 1) return name_ref(k_, t.word, at(t));  // rejects: ambiguous_person
    std::vector<std::string> people;
    for (const Person& p : k_.people) {
      people.push_back(p.name);
      people.insert(people.end(), p.roles.begin(), p.roles.end());
    }
    const auto close = closest_names(t.word, people);
    reject(RejectReason::unknown_person,
           "nobody is called '" + t.word + "'" + (close.empty() ? "" : "; " + did_you_mean(close)),
           at(t), close);
  }

  // The place phrase from the cursor up to the next phrase start ("in room ..." belongs to it).
  PlaceRef place_phrase() {
    if (done() || ends_phrase(i_))
      reject(RejectReason::missing_place, "a place or person is missing here", here());
    // One "in" belongs to the phrase ("the desk in room A-114"); a second one starts the next.
    std::size_t stop = i_;
    bool seen_in = false;
    while (stop < t_.size() && !ends_phrase(stop)) {
      if (t_[stop].word == "in" && std::exchange(seen_in, true)) break;
      ++stop;
    }
    const std::size_t begin = i_;
    i_ = stop;
    return resolve_place(begin, stop);
  }

  const Place* room_named(std::size_t from, std::size_t to, const Located& where) {
    if (from < to && t_[from].word == "room") ++from;
    if (from == to) reject(RejectReason::missing_place, "say which room", where);
    const Place* room = k_.find_place(joined(t_, from, to, '-'));
    if (room == nullptr) room = k_.find_place(joined(t_, from, to, ' '));
    if (room == nullptr || room->kind != PlaceKind::room) {
      const auto close = closest_names(joined(t_, from, to, '-'), names_of(k_.rooms()));
      reject(RejectReason::unknown_room,
             "no room '" + written(t_, from, to) + "'" +
                 (close.empty() ? "" : "; " + did_you_mean(close)),
             at(t_[from]), close);
    }
    return room;
  }

  void check_in_room(const std::string& place, const Place* room, const Located& where) {
    const Place* p = k_.find_place(place);
    if (room != nullptr && p != nullptr && !same_name(p->room, room->name))
      reject(RejectReason::place_not_in_room,
             place + " is in " + (p->room.empty() ? "no room" : p->room) + ", not in " + room->name,
             where, names_of(k_.places_in_room(room->name)));
  }

  PlaceRef resolve_place(std::size_t begin, std::size_t stop) {
    // Split "the desk in room A-114" into the place words and the room.
    std::size_t in = begin;
    while (in < stop && t_[in].word != "in") ++in;
    const Place* room = nullptr;
    if (in < stop) {
      const Located after =
          in + 1 < stop ? at(t_[in + 1]) : (stop < t_.size() ? at(t_[stop]) : end());
      room = room_named(in + 1, stop, after);
    }
    std::size_t from = begin;
    if (from < in && is_article(t_[from].word)) ++from;
    const Located where = from < in ? at(t_[from]) : (in < stop ? at(t_[in]) : here());
    if (from == in) {
      if (room != nullptr) return room_ref(k_, *room, where);
      reject(RejectReason::missing_place, "a place or person is missing here", where);
    }
    if (t_[from].word == "room") {
      if (room != nullptr) unexpected_at(in, "a room is said twice");
      const Place* r = room_named(from, in, where);
      return room_ref(k_, *r, where);
    }
    for (std::size_t j = from; j < in; ++j)
      if (t_[j].possessive && j != from)
        unexpected_at(j, "a possessive comes first ('Michael's desk')");
    if (t_[from].possessive) {
      PlaceRef ref = person_by_possessive(t_[from]);
      const Place* desk = k_.find_place(ref.place);
      for (std::size_t j = from + 1; j < in; ++j)
        if (desk != nullptr && !describes(t_[j].word, *desk) &&
            !is_one_of(t_[j].word, {"place", "office"}))
          reject(RejectReason::unknown_place,
                 ref.person + " sits at " + desk->name + ", a " + to_string(desk->kind) + "; '" +
                     t_[j].text + "' does not describe it",
                 at(t_[j]), {desk->name});
      check_in_room(ref.place, room, where);
      return ref;
    }
    // A name of a place, room or person, possibly written in words ("meeting table").
    for (char sep : {'-', ' ', '\0'}) {
      const std::string name = joined(t_, from, in, sep);
      const NameMeaning m = lookup_name(k_, name);
      if (m.empty()) continue;
      if (m.place != nullptr && m.place->kind == PlaceKind::room && room != nullptr)
        unexpected_at(in, "a room is said twice");
      PlaceRef ref = name_ref(k_, name, where);
      check_in_room(ref.place, room, where);
      return ref;
    }
    // Words describing a place ("the desk", "the table in room A-111").
    std::vector<const Place*> fits;
    for (const Place& p : k_.places) {
      if (p.kind == PlaceKind::room || (room != nullptr && !same_name(p.room, room->name)))
        continue;
      bool all = true;
      for (std::size_t j = from; j < in && all; ++j) all = describes(t_[j].word, p);
      if (all) fits.push_back(&p);
    }
    const std::string words = written(t_, from, in);
    if (fits.size() == 1) return place_ref(k_, *fits[0], where);
    if (fits.size() > 1) {
      std::vector<std::string> names = names_of(fits);
      if (names.size() > 5) names.resize(5);
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      if (fits.size() > names.size()) list += ", ...";
      reject(RejectReason::ambiguous_place,
             std::to_string(fits.size()) + " places fit '" + words + "' (" + list +
                 "); say which room or name it",
             where, names);
    }
    if (room != nullptr) {
      const auto there = names_of(k_.places_in_room(room->name));
      reject(RejectReason::place_not_in_room,
             "no " + words + " in room " + room->name +
                 (there.empty() ? ""
                                : "; there: " + there.front() + (there.size() > 1 ? ", ..." : "")),
             where, there);
    }
    if (starts_with_digit(t_[from].word))
      reject(RejectReason::unknown_place,
             "no place '" + words + "'; a deadline is said with 'by', 'before' or 'within'", where);
    const auto close = closest_names(joined(t_, from, in, '-'), known_names(k_));
    reject(RejectReason::unknown_place,
           "no place or person '" + words + "'" + (close.empty() ? "" : "; " + did_you_mean(close)),
           where, close);
  }

  [[noreturn]] void unexpected_at(std::size_t j, const std::string& why) const {
    reject(RejectReason::unexpected_word, "unexpected '" + t_[j].text + "': " + why, at(t_[j]));
  }

  // ---- deadlines -----------------------------------------------------------------------------
  // "by 10:30", "before 11", "until 2 pm", "within 20 minutes", "in half an hour".
  double deadline() {
    const Token& keyword = t_[i_++];
    if (keyword.word == "within" || keyword.word == "in") return duration_from_now(keyword);
    return clock_value();
  }

  double clock_value() {
    if (done()) reject(RejectReason::bad_time, "a time of day is missing, e.g. 10:30", end());
    const Token& t = t_[i_++];
    std::string w = t.word;
    std::string meridiem;
    if (w.size() > 2 &&
        (w.compare(w.size() - 2, 2, "am") == 0 || w.compare(w.size() - 2, 2, "pm") == 0)) {
      meridiem = w.substr(w.size() - 2);
      w.resize(w.size() - 2);
    } else if (next_is("am") || next_is("pm")) {
      meridiem = t_[i_++].word;
    }
    std::replace(w.begin(), w.end(), '.', ':');
    std::optional<double> s;
    if (w == "noon" && meridiem.empty())
      s = 12 * 3600.0;
    else if (!w.empty() && w.size() <= 2 &&
             std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; }))
      s = std::stoi(w) * 3600.0;
    else
      s = parse_clock(w);
    if (s && *s > kSecondsPerDay) s.reset();
    if (s && !meridiem.empty()) {
      const int hour = static_cast<int>(*s / 3600.0);
      if (hour < 1 || hour > 12)
        s.reset();
      else if (meridiem == "pm" && hour != 12)
        *s += 12 * 3600.0;
      else if (meridiem == "am" && hour == 12)
        *s -= 12 * 3600.0;
    }
    if (!s)
      reject(RejectReason::bad_time,
             "'" + t.text + "' is not a time of day; write it as 10:30, 11 or 2 pm", at(t));
    check_deadline(*s, now_, at(t));
    return *s;
  }

  double duration_from_now(const Token& keyword) {
    if (done())
      reject(RejectReason::bad_time, "how long is missing, e.g. 'within 20 minutes'", end());
    const Token& amount = t_[i_];
    double count = 0.0;
    std::string unit;
    if (amount.word == "half") {  // "half an hour"
      ++i_;
      if (next_is("an") || next_is("a")) ++i_;
      count = 0.5;
    } else if (amount.word == "an" || amount.word == "a") {
      ++i_;
      count = 1.0;
    } else {
      std::size_t digits = 0;
      while (digits < amount.word.size() && amount.word[digits] >= '0' &&
             amount.word[digits] <= '9')
        ++digits;
      if (digits == 0 || digits > 5)
        reject(RejectReason::bad_time, "'" + amount.text + "' is not a number of minutes or hours",
               at(amount));
      count = std::stod(amount.word.substr(0, digits));
      unit = amount.word.substr(digits);  // "20min"
      ++i_;
    }
    if (unit.empty()) {
      if (done())
        reject(RejectReason::bad_time, "'" + keyword.text + "' needs a unit: minutes or hours",
               end());
      unit = t_[i_++].word;
    }
    double seconds_per = 0.0;
    if (is_one_of(unit, {"minute", "minutes", "min", "mins"})) seconds_per = 60.0;
    if (is_one_of(unit, {"hour", "hours", "h", "hr", "hrs"})) seconds_per = 3600.0;
    if (seconds_per == 0.0)
      reject(RejectReason::bad_time,
             "'" + t_[i_ - 1].text + "' is not a unit of time; say minutes or hours",
             at(t_[i_ - 1]));
    const double deadline = now_ + count * seconds_per;
    check_deadline(deadline, now_, at(amount));
    return deadline;
  }

  std::string_view text_;
  const OfficeKnowledge& k_;
  double now_;
  std::vector<Token> t_;
  std::size_t i_ = 0;
};

}  // namespace

CommandAnswer interpret_command(std::string_view text, const OfficeKnowledge& knowledge,
                                double now_sim_s) {
  CommandAnswer answer;
  try {
    answer = TextInterpreter(text, knowledge, knowledge.clock.time_of_day(now_sim_s)).run();
  } catch (const RejectionError& e) {
    answer = CommandAnswer{};
    answer.kind = CommandAnswer::Kind::rejected;
    answer.rejection = e.rejection;
  }
  return answer;
}

}  // namespace autonomy::courier
