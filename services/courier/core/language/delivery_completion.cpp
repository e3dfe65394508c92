#include "services/courier/core/language/delivery_completion.hpp"

#include "services/courier/core/knowledge/name_lookup.hpp"
#include "services/courier/core/knowledge/office_knowledge.hpp"

#include <algorithm>

namespace autonomy::courier {

namespace {

// Words understood even when no such object is known yet: a command may announce an object the
// courier has not seen ("put the red letter on the meeting table ...").
const char* const kCommonKinds[] = {"letter",   "book",   "envelope", "parcel", "package",
                                    "document", "folder", "file",     "note",   "box"};
const char* const kCommonColours[] = {"red",   "green",  "blue",   "yellow", "white", "black",
                                      "brown", "orange", "purple", "pink",   "grey",  "gray"};

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) out += i + 1 == words.size() ? " and " : ", ";
    out += words[i];
  }
  return out;
}

std::string describe(const ObjectDescription& o) {
  return o.colour.empty() ? o.kind : o.colour + " " + o.kind;
}

std::string plural(const std::string& kind) {
  return kind.empty() ? "objects" : (kind.back() == 'x' ? kind + "es" : kind + "s");
}

// "Wolfram's desk", "the librarian's desk", or the place name when nobody sits there.
std::string place_phrase(const OfficeKnowledge& k, const std::string& place) {
  const Place* p = k.find_place(place);
  const Person* who = k.person_at(place);
  if (p == nullptr || who == nullptr) return place;
  return person_phrase(*who) + "'s " + to_string(p->kind);
}

// "Wolfram's desk (a118-desk)", or just "meeting-table" when nobody sits there.
std::string place_with_name(const OfficeKnowledge& k, const std::string& place) {
  const std::string phrase = place_phrase(k, place);
  return phrase == place ? place : phrase + " (" + place + ")";
}

std::string on_or_at(const OfficeKnowledge& k, const std::string& place) {
  const Place* p = k.find_place(place);
  return p != nullptr && (p->kind == PlaceKind::desk || p->kind == PlaceKind::table) ? "on" : "at";
}

std::vector<std::string> ids_of(const std::vector<const KnownObject*>& objects) {
  std::vector<std::string> ids;
  for (const KnownObject* o : objects) ids.push_back(o->id);
  return ids;
}

}  // namespace

void reject(RejectReason reason, std::string message, const Located& at,
            std::vector<std::string> suggestions) {
  Rejection r;
  r.reason = reason;
  r.message = std::move(message);
  r.word = at.word;
  r.column = at.column;
  r.field = at.field;
  r.suggestions = std::move(suggestions);
  throw RejectionError(std::move(r));
}

std::string person_phrase(const Person& person) {
  const bool common_noun = !person.name.empty() && person.name[0] >= 'a' && person.name[0] <= 'z';
  return common_noun ? "the " + person.name : person.name;
}

PlaceRef place_ref(const OfficeKnowledge& k, const Place& place, const Located& at) {
  PlaceRef ref;
  ref.place = place.name;
  if (const Person* who = k.person_at(place.name)) ref.person = who->name;
  ref.at = at;
  return ref;
}

PlaceRef person_ref(const OfficeKnowledge& k, const Person& person, const Located& at) {
  PlaceRef ref;
  ref.place = person.desk;
  ref.person = person.name;
  const Place* desk = k.find_place(person.desk);
  ref.assumption = person_phrase(person) + "'s " + (desk ? to_string(desk->kind) : "place") + " (" +
                   person.desk + ")";
  ref.at = at;
  return ref;
}

PlaceRef room_ref(const OfficeKnowledge& k, const Place& room, const Located& at) {
  const std::vector<const Place*> inside = k.places_in_room(room.name);
  std::vector<const Place*> desks, stations;
  for (const Place* p : inside) {
    if (k.person_at(p->name) != nullptr) desks.push_back(p);
    if (k.station_at(p->name) != nullptr) stations.push_back(p);
  }
  const Place* chosen = nullptr;
  std::string why;
  if (desks.size() == 1) {
    chosen = desks[0];
    why = place_with_name(k, chosen->name);
  } else if (desks.empty() && stations.size() == 1) {
    chosen = stations[0];
    why = "the loading station " + chosen->name;
  } else if (desks.empty() && inside.size() == 1) {
    chosen = inside[0];
    why = chosen->name;
  }
  if (chosen == nullptr) {
    std::vector<std::string> names;
    for (const Place* p : (desks.empty() ? inside : desks)) names.push_back(p->name);
    if (names.empty())
      reject(RejectReason::ambiguous_place,
             "room " + room.name + " has no place to hand things over; name a place or a person",
             at);
    reject(RejectReason::ambiguous_place,
           "room " + room.name + " has several places (" + join(names) + "); say which", at, names);
  }
  PlaceRef ref = place_ref(k, *chosen, at);
  ref.assumption = "room " + room.name + " means " + why;
  return ref;
}

PlaceRef name_ref(const OfficeKnowledge& k, const std::string& name, const Located& at) {
  const NameMeaning meaning = lookup_name(k, name);
  if (meaning.place != nullptr)
    return meaning.place->kind == PlaceKind::room ? room_ref(k, *meaning.place, at)
                                                  : place_ref(k, *meaning.place, at);
  if (meaning.people.size() == 1) return person_ref(k, *meaning.people[0], at);
  if (meaning.people.size() > 1) {
    std::vector<std::string> names;
    for (const Person* p : meaning.people) names.push_back(p->name);
    reject(RejectReason::ambiguous_person,
           "'" + name + "' may be " + join(names) + "; say whom by name", at, names);
  }
  const std::vector<std::string> close = closest_names(name, known_names(k));
  std::string message = "no place or person '" + name + "'";
  if (!close.empty()) message += "; " + did_you_mean(close);
  reject(RejectReason::unknown_place, message, at, close);
}

std::vector<std::string> object_kind_words(const OfficeKnowledge& k) {
  std::vector<std::string> words = k.object_kinds();
  for (const char* w : kCommonKinds)
    if (!is_word_in(w, words)) words.push_back(w);
  return words;
}

std::vector<std::string> colour_words(const OfficeKnowledge& k) {
  std::vector<std::string> words = k.colours();
  for (const char* w : kCommonColours)
    if (!is_word_in(w, words)) words.push_back(w);
  return words;
}

bool is_word_in(std::string_view word, const std::vector<std::string>& words) {
  return std::any_of(words.begin(), words.end(),
                     [&](const std::string& w) { return same_name(w, word); });
}

void check_deadline(double deadline_s, double now_of_day_s, const Located& at) {
  if (deadline_s > kSecondsPerDay)
    reject(RejectReason::deadline_after_midnight,
           "the deadline falls after midnight; deadlines are times of the current day", at);
  if (deadline_s <= now_of_day_s)
    reject(RejectReason::deadline_in_past,
           "the deadline " + format_clock(deadline_s) + " is not after now (" +
               format_clock(now_of_day_s) + ")",
           at);
}

Interpretation complete_delivery(const DeliveryDraft& d, const OfficeKnowledge& k) {
  Interpretation out;
  out.object = d.object;
  std::optional<PlaceRef> pickup = d.pickup;
  auto assume = [&](const std::string& what, const std::string& text) {
    if (!text.empty()) out.assumptions.push_back(what + ": " + text);
  };
  if (pickup) assume("pickup", pickup->assumption);

  // The object: by id, or the one of that description known at the pickup place (or anywhere).
  if (!d.object.id.empty()) {
    const KnownObject* o = k.find_object(d.object.id);
    if (o == nullptr) {
      const std::vector<std::string> close =
          closest_names(d.object.id, ids_of(k.objects_matching("", "")));
      reject(RejectReason::unknown_object,
             "no object '" + d.object.id + "'" + (close.empty() ? "" : "; " + did_you_mean(close)),
             d.object_at, close);
    }
    if ((!d.object.kind.empty() && !same_name(d.object.kind, o->kind)) ||
        (!d.object.colour.empty() && !same_name(d.object.colour, o->colour)))
      reject(RejectReason::unknown_object,
             o->id + " is a " + describe({lower_case(o->kind), lower_case(o->colour), ""}) +
                 ", not a " + describe(d.object),
             d.object_at);
    out.object = {lower_case(o->kind), lower_case(o->colour), o->id};
    if (!o->carrier.empty())
      reject(RejectReason::object_aboard,
             o->id + " is aboard " + o->carrier + " already; change the destination of its job",
             d.object_at);
    if (o->place.empty())
      reject(RejectReason::missing_pickup,
             "where " + o->id + " is is not known; say where to pick it up", d.object_at);
    if (pickup && !same_name(pickup->place, o->place))
      reject(RejectReason::object_elsewhere,
             o->id + " is known to be at " + o->place + ", not at " + pickup->place, pickup->at);
    if (!pickup) {
      pickup = place_ref(k, *k.find_place(o->place), d.object_at);
      assume("pickup", place_with_name(k, o->place) + ", where " + o->id + " is known to be");
    }
  } else if (pickup) {
    const auto there = k.objects_matching(d.object.kind, d.object.colour, pickup->place);
    if (there.size() > 1)
      reject(RejectReason::ambiguous_object,
             "there are " + std::to_string(there.size()) + " " + plural(describe(d.object)) +
                 " at " + pickup->place + " (" + join(ids_of(there)) +
                 "); say which by its colour or id",
             d.object_at, ids_of(there));
    if (there.size() == 1) {
      out.object.id = there[0]->id;
      out.object.colour = lower_case(there[0]->colour);
      assume("object", "the " + describe(out.object) + " known to be " +
                           on_or_at(k, pickup->place) + " " + place_phrase(k, pickup->place) +
                           " (" + there[0]->id + ")");
    } else {
      assume("object", "a " + describe(d.object) + " not yet known to be at " + pickup->place +
                           "; it is to be handed over there");
    }
  } else {
    const auto anywhere = k.objects_matching(d.object.kind, d.object.colour);
    if (anywhere.empty())
      reject(RejectReason::missing_pickup,
             "no " + describe(d.object) + " is known to be anywhere; say where to pick it up",
             d.missing_pickup);
    if (anywhere.size() > 1)
      reject(RejectReason::ambiguous_object,
             std::to_string(anywhere.size()) + " " + plural(describe(d.object)) + " are known (" +
                 join(ids_of(anywhere)) + "); say which or where to pick it up",
             d.object_at, ids_of(anywhere));
    const KnownObject& o = *anywhere[0];
    out.object = {lower_case(o.kind), lower_case(o.colour), o.id};
    pickup = place_ref(k, *k.find_place(o.place), d.object_at);
    assume("pickup", place_with_name(k, o.place) + ", where the " + describe(out.object) +
                         " is known to be (" + o.id + ")");
  }
  out.pickup_place = pickup->place;
  out.pickup_person = pickup->person;

  // The destination: as said, else the object's addressee, else the most frequent one learned.
  std::optional<PlaceRef> delivery = d.delivery;
  if (delivery) {
    assume("destination", delivery->assumption);
  } else {
    const KnownObject* o = out.object.id.empty() ? nullptr : k.find_object(out.object.id);
    const Person* addressee = o && !o->addressee.empty() ? k.find_person(o->addressee) : nullptr;
    if (addressee != nullptr) {
      delivery = person_ref(k, *addressee, d.end);
      assume("destination", person_phrase(*addressee) + ", the addressee of " + o->id + " (" +
                                addressee->desk + ")");
    } else {
      const std::string source = pickup->person.empty() ? pickup->place : pickup->person;
      const auto learned = k.learned.most_frequent_destination(source, out.object.kind);
      const Place* place = learned ? k.find_place(learned->destination) : nullptr;
      if (place == nullptr)
        reject(RejectReason::missing_destination,
               "where to deliver the " + describe(out.object) +
                   " is not said, and no destination of " + plural(out.object.kind) + " from " +
                   source + " has been learned; say 'to' a place or person",
               d.end);
      delivery = place_ref(k, *place, d.end);
      const std::string who = delivery->person.empty() ? place->name : delivery->person;
      assume("destination", who + ", the most frequent destination of " + plural(out.object.kind) +
                                " from " + source + " (" + place->name + ", " +
                                std::to_string(learned->count) + " of " +
                                std::to_string(learned->total) + ")");
    }
  }
  if (same_name(delivery->place, pickup->place))
    reject(RejectReason::same_place,
           "the " + describe(out.object) + " is to be picked up and delivered at the same place (" +
               pickup->place + ")",
           delivery->at.column > 0 || !delivery->at.field.empty() ? delivery->at : d.end);
  out.delivery_place = delivery->place;
  out.delivery_person = delivery->person;
  out.deadline_s = d.deadline_s;
  return out;
}

}  // namespace autonomy::courier
