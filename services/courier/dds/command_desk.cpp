#include "services/courier/dds/command_desk.hpp"

#include "common/msg/text_limits.hpp"
#include "services/courier/core/knowledge/name_lookup.hpp"
#include "services/courier/core/language/command_interpreter.hpp"
#include "services/courier/core/language/structured_request.hpp"

#include <nlohmann/json.hpp>

namespace autonomy::courier {

namespace {

msg::CourierReply rejected(const msg::CourierCommand& c, std::string reason, std::string detail) {
  msg::CourierReply r;
  r.command_id = msg::clipped_id(c.command_id);
  r.accepted = false;
  r.reason = std::move(reason);
  r.detail = std::move(detail);
  return r;
}

msg::CourierReply from_rejection(const msg::CourierCommand& c, const Rejection& x) {
  msg::CourierReply r = rejected(c, to_string(x.reason), x.message);
  r.word = x.word;
  r.column = x.column;
  r.suggestions = x.suggestions;
  return r;
}

std::string clock_or_empty(const std::optional<double>& s) { return s ? format_clock(*s) : std::string(); }

std::string object_words(const ObjectDescription& o) {
  std::string text = "the " + (o.colour.empty() ? "" : o.colour + " ") + o.kind;
  if (!o.id.empty()) text += " (" + o.id + ")";
  return text;
}

}  // namespace

CommandDesk::CommandDesk(const OfficeKnowledge& knowledge, CourierExecutive& executive, Journal& journal,
                         int jobs_created)
    : knowledge_(knowledge), executive_(executive), journal_(journal), jobs_created_(jobs_created) {}

msg::CourierReply CommandDesk::handle(const msg::CourierCommand& c, double now_sim_s, int64_t tick) {
  msg::CourierReply reply;
  if (c.command_id.empty()) {
    reply = rejected(c, "invalid_command", "command_id is empty");
    reply.tick = tick;
    return reply;  // nothing to journal it under
  }
  if (auto problem = msg::first_length_problem({{"command_id", c.command_id, msg::kMaxIdLength},
                                                {"requester", c.requester, msg::kMaxNameLength},
                                                {"text", c.text, msg::kMaxTextLength},
                                                {"job_id", c.job_id, msg::kMaxIdLength},
                                                {"object_id", c.object_id, msg::kMaxNameLength},
                                                {"object_kind", c.object_kind, msg::kMaxNameLength},
                                                {"object_colour", c.object_colour, msg::kMaxNameLength},
                                                {"from", c.from, msg::kMaxNameLength},
                                                {"to", c.to, msg::kMaxNameLength},
                                                {"deadline", c.deadline, msg::kMaxNameLength}})) {
    reply = rejected(c, "too_long", *problem);
    reply.tick = tick;
    // An overlong id is not journalled (it could not be asked for again under that id anyway).
    if (c.command_id.size() <= msg::kMaxIdLength) journal_.record_command(c.command_id, reply_to_json(reply), nullptr);
    return reply;
  }
  if (auto earlier = journal_.reply_for(c.command_id)) return reply_from_json(*earlier, c.command_id);

  switch (c.kind) {
    case msg::CourierCommandKind::Text:
    case msg::CourierCommandKind::Deliver: reply = deliver(c, now_sim_s); break;
    case msg::CourierCommandKind::Cancel:
    case msg::CourierCommandKind::Revise: reply = revise(c, now_sim_s); break;
    default: reply = rejected(c, "invalid_command", "kind is not text, deliver, cancel or revise"); break;
  }
  reply.tick = tick;
  // A new job was journalled with its reply in accept_delivery(); everything else is journalled
  // here, before the reply is published, so a repeat after a crash gets the same answer.
  if (!reply.accepted) journal_.record_command(c.command_id, reply_to_json(reply), nullptr);
  return reply;
}

OfficeKnowledge CommandDesk::believed_knowledge() const {
  // What the office file says, with each object where the courier's jobs left it (delivered,
  // returned, aboard): commands are read against where things are now.
  OfficeKnowledge k = knowledge_;
  const auto whereabouts = executive_.object_whereabouts();
  for (KnownObject& o : k.objects) {
    const auto it = whereabouts.find(o.id);
    if (it == whereabouts.end()) continue;
    o.place = it->second.place;
    o.carrier = it->second.carrier;
  }
  return k;
}

msg::CourierReply CommandDesk::deliver(const msg::CourierCommand& c, double now_sim_s) {
  const OfficeKnowledge knowledge = believed_knowledge();
  CommandAnswer answer;
  if (c.kind == msg::CourierCommandKind::Text) {
    answer = interpret_command(c.text, knowledge, now_sim_s);
  } else {
    StructuredRequest request;
    request.object_id = c.object_id;
    request.kind = c.object_kind;
    request.colour = c.object_colour;
    request.from = c.from;
    request.to = c.to;
    request.deadline = c.deadline;
    answer = interpret_request(request, knowledge, now_sim_s);
  }
  switch (answer.kind) {
    case CommandAnswer::Kind::rejected: return from_rejection(c, answer.rejection);
    case CommandAnswer::Kind::revision: return apply_revision(c, answer.revision, now_sim_s);
    case CommandAnswer::Kind::delivery: return accept_delivery(c, answer.delivery, now_sim_s);
  }
  return rejected(c, "invalid_command", "unreadable command");
}

msg::CourierReply CommandDesk::accept_delivery(const msg::CourierCommand& c, const Interpretation& i,
                                               double now_sim_s) {
  // The simulator's handovers name objects by id: one the courier does not know cannot be asked for.
  if (i.object.id.empty()) {
    msg::CourierReply r = rejected(c, "unknown_object",
                                   "no " + object_words(i.object).substr(4) + " is known to be at " + i.pickup_place +
                                       "; name a known object or its place");
    r.word = i.object.kind;
    return r;
  }
  // One object is in one open job: a second one would find it gone (object_not_at_place).
  if (const Job* holder = executive_.open_job_of_object(i.object.id)) {
    msg::CourierReply r = rejected(c, "object_in_open_job",
                                   i.object.id + " is in open job " + holder->id + " (to " + holder->destination +
                                       ", " + to_string(holder->state) + "); cancel or revise that job instead");
    r.word = i.object.id;
    r.job_id = holder->id;
    return r;
  }
  Job job;
  job.id = "job-" + std::to_string(jobs_created_ + 1);
  job.command_id = c.command_id;
  const KnownObject* known = knowledge_.find_object(i.object.id);
  job.object = {i.object.id, known ? known->kind : i.object.kind, known ? known->colour : i.object.colour};
  job.pickup = i.pickup_place;
  job.destination = i.delivery_place;
  job.deadline_s = i.deadline_s;
  job.object_place = i.pickup_place;

  msg::CourierReply r;
  r.command_id = c.command_id;
  r.accepted = true;
  r.job_id = job.id;
  r.action = "deliver";
  r.object = object_words(i.object);
  r.from = i.pickup_place;
  r.to = i.delivery_place;
  r.deadline = clock_or_empty(i.deadline_s);
  r.assumptions = i.assumptions;
  // Journalled first: an acceptance is never published for a job that a crash could lose.
  journal_.record_command(c.command_id, reply_to_json(r), &job);
  ++jobs_created_;
  executive_.add_job(std::move(job), knowledge_.clock.time_of_day(now_sim_s));
  return r;
}

msg::CourierReply CommandDesk::revise(const msg::CourierCommand& c, double now_sim_s) {
  if (c.job_id.empty()) return rejected(c, "missing_job", "job_id is empty");
  Revision r;
  r.kind = c.kind == msg::CourierCommandKind::Cancel ? Revision::Kind::cancel : Revision::Kind::change;
  r.job = c.job_id;
  if (r.kind == Revision::Kind::change) {
    if (c.to.empty() && c.deadline.empty()) return rejected(c, "nothing_to_change", "neither to nor deadline is set");
    if (!c.to.empty()) {
      const NameMeaning meaning = lookup_name(knowledge_, c.to);
      if (meaning.place && meaning.place->kind != PlaceKind::room) {
        r.delivery_place = meaning.place->name;
      } else if (meaning.place) {
        const auto inside = knowledge_.places_in_room(meaning.place->name);
        if (inside.size() != 1)
          return rejected(c, "ambiguous_place", "room " + meaning.place->name + " has " +
                                                    std::to_string(inside.size()) + " places; name one");
        r.delivery_place = inside.front()->name;
      } else if (meaning.people.size() == 1) {
        r.delivery_place = meaning.people.front()->desk;
        r.delivery_person = meaning.people.front()->name;
      } else {
        msg::CourierReply x = rejected(c, meaning.people.empty() ? "unknown_place" : "ambiguous_person",
                                       "no single place '" + c.to + "'");
        x.word = c.to;
        x.suggestions = closest_names(c.to, known_names(knowledge_));
        if (!x.suggestions.empty()) x.detail += "; " + did_you_mean(x.suggestions);
        return x;
      }
    }
    if (!c.deadline.empty()) {
      const auto deadline = parse_clock(c.deadline);
      if (!deadline) {
        msg::CourierReply x = rejected(c, "bad_time", "deadline '" + c.deadline + "' is not HH:MM");
        x.word = c.deadline;
        return x;
      }
      if (*deadline <= knowledge_.clock.time_of_day(now_sim_s))
        return rejected(c, "deadline_in_past", "deadline " + c.deadline + " has passed");
      r.deadline_s = deadline;
    }
  }
  return apply_revision(c, r, now_sim_s);
}

msg::CourierReply CommandDesk::apply_revision(const msg::CourierCommand& c, const Revision& r, double now_sim_s) {
  const double now_day = knowledge_.clock.time_of_day(now_sim_s);
  std::optional<std::string> error;
  if (r.kind == Revision::Kind::cancel) {
    error = executive_.cancel(r.job, c.requester.empty() ? "" : "by " + c.requester, now_day);
  } else {
    std::optional<std::string> destination;
    if (!r.delivery_place.empty()) destination = r.delivery_place;
    std::optional<std::optional<double>> deadline;
    if (r.deadline_s) deadline = r.deadline_s;
    error = executive_.revise(r.job, destination, deadline, now_day);
  }
  msg::CourierReply reply;
  reply.command_id = c.command_id;
  reply.job_id = r.job;
  reply.action = r.kind == Revision::Kind::cancel ? "cancel" : "revise";
  if (error) {
    reply = rejected(c, executive_.job(r.job) ? "job_not_changeable" : "unknown_job", *error);
    reply.job_id = r.job;
    reply.action = r.kind == Revision::Kind::cancel ? "cancel" : "revise";
    reply.word = r.job;
    reply.column = r.job_column;
    return reply;
  }
  reply.accepted = true;
  if (const Job* job = executive_.job(r.job)) {
    reply.object = job->object.id;
    reply.from = job->pickup;
    reply.to = job->destination;
    reply.deadline = clock_or_empty(job->deadline_s);
  }
  reply.assumptions = r.assumptions;
  // The changed job with the reply, before the reply is published: a restart keeps the change.
  journal_.record_command(c.command_id, reply_to_json(reply), executive_.job(r.job), false);
  return reply;
}

std::string reply_to_json(const msg::CourierReply& r) {
  nlohmann::json j = {{"command_id", r.command_id}, {"accepted", r.accepted},   {"job_id", r.job_id},
                      {"action", r.action},         {"object", r.object},       {"from", r.from},
                      {"to", r.to},                 {"deadline", r.deadline},   {"assumptions", r.assumptions},
                      {"reason", r.reason},         {"detail", r.detail},       {"word", r.word},
                      {"column", r.column},         {"suggestions", r.suggestions}, {"tick", r.tick}};
  return j.dump();
}

msg::CourierReply reply_from_json(const std::string& text, const std::string& command_id) {
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    msg::CourierReply r;
    r.command_id = j.at("command_id").get<std::string>();
    r.accepted = j.at("accepted").get<bool>();
    r.job_id = j.at("job_id").get<std::string>();
    r.action = j.at("action").get<std::string>();
    r.object = j.at("object").get<std::string>();
    r.from = j.at("from").get<std::string>();
    r.to = j.at("to").get<std::string>();
    r.deadline = j.at("deadline").get<std::string>();
    r.assumptions = j.at("assumptions").get<std::vector<std::string>>();
    r.reason = j.at("reason").get<std::string>();
    r.detail = j.at("detail").get<std::string>();
    r.word = j.at("word").get<std::string>();
    r.column = j.at("column").get<int32_t>();
    r.suggestions = j.at("suggestions").get<std::vector<std::string>>();
    r.tick = j.at("tick").get<int64_t>();
    return r;
  } catch (const nlohmann::json::exception& e) {
    msg::CourierReply r;
    r.command_id = command_id;
    r.reason = "journal_damaged";
    r.detail = std::string("the journalled reply cannot be read: ") + e.what();
    return r;
  }
}

}  // namespace autonomy::courier
