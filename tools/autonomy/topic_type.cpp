// autonomy topic type TOPIC, autonomy interface show TYPE: a type as IDL text, from the type
// information in the domain (the catalogue's types compiled in, other processes' types from
// discovery), so it shows what is on the wire, for any topic.
#include <iostream>
#include <memory>

#include "common/dds/error.hpp"
#include "tools/autonomy/commands.hpp"
#include "tools/autonomy/discovered_reader.hpp"
#include "tools/autonomy/suggest.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/type_idl.hpp"
#include "tools/xtypes/type_lookup.hpp"

namespace autonomy::tools {

namespace {

struct TypeOptions {
  int domain = 0;
  std::string name;
  double discovery_s = 1.0;
};

// The catalogue topic's type, from the type information idlc compiled in (no other process needed).
xtypes::TypePtr catalogue_type(const dds::Participant& participant, const recording::RecordableTopic& topic) {
  dds::Entity entity(dds::check(dds_create_topic(participant.handle(), topic.descriptor, topic.name.c_str(), nullptr, nullptr),
                                "dds_create_topic " + topic.name));
  return xtypes::TypeLookup(participant.handle(), DDS_SECS(1)).resolve_entity(entity.handle());
}

int run_topic_type(const TypeOptions& o, Context& ctx) {
  dds::Participant participant(o.domain);
  if (const auto* known = recording::find_recordable(o.name)) {
    std::cout << xtypes::to_idl(catalogue_type(participant, *known));
    return kExitOk;
  }
  Interrupt interrupt(ctx.signals, participant);
  try {
    if (const auto found = find_discovered_topic(participant, o.name, interrupt, seconds(o.discovery_s))) {
      std::cout << xtypes::to_idl(found->type);
      return kExitOk;
    }
  } catch (const xtypes::TypeLookupError& e) {
    std::cerr << "autonomy topic type: " << o.name << ": " << e.what() << "\n";
    return kExitFailed;
  }
  std::vector<std::string> names;
  for (const auto& t : recording::recordable_topics()) names.push_back(t.name);
  for (auto& n : discovered_topic_names(participant)) names.push_back(n);
  std::cerr << unknown_topic_message("autonomy topic type", o.name, names) << " (not in the catalogue, and no process on domain "
            << o.domain << " has an endpoint of it within " << o.discovery_s << " s)\n";
  return kExitUsage;
}

// "NavGoal", "autonomy::NavGoal" or "autonomy/NavGoal" name the same type.
bool same_type_name(const std::string& asked, const std::string& type_name) {
  std::string a = asked;
  for (size_t at; (at = a.find('/')) != std::string::npos;) a.replace(at, 1, "::");
  if (a == type_name) return true;
  const auto cut = type_name.rfind("::");
  return cut != std::string::npos && a == type_name.substr(cut + 2);
}

int run_interface_show(const TypeOptions& o, Context& ctx) {
  dds::Participant participant(o.domain);
  std::vector<std::string> known;
  for (const auto& t : recording::recordable_topics()) {
    if (same_type_name(o.name, t.type_name)) {
      std::cout << xtypes::to_idl(catalogue_type(participant, t));
      return kExitOk;
    }
    known.push_back(t.type_name.substr(t.type_name.rfind(':') + 1));  // short names: what people type
  }
  // Not ours: the type of some topic another process announced.
  Interrupt interrupt(ctx.signals, participant);
  sleep_for(interrupt, participant, seconds(o.discovery_s));
  xtypes::TopicTypeFinder finder(participant.handle());
  for (const auto& topic : finder.topic_names()) {
    try {
      const auto found = finder.find(topic, DDS_SECS(5));
      if (!found) continue;
      if (same_type_name(o.name, found->type_name)) {
        std::cout << xtypes::to_idl(found->type);
        return kExitOk;
      }
      known.push_back(found->type_name);
    } catch (const xtypes::TypeLookupError&) {
      continue;  // a topic without usable type information cannot be the one asked for
    }
  }
  const std::string hint = did_you_mean(o.name, known);
  std::cerr << "autonomy interface show: unknown type \"" << o.name << "\"" << (hint.empty() ? "" : "; " + hint)
            << " (neither a catalogue type nor the type of a topic on domain " << o.domain << ")\n";
  return kExitUsage;
}

}  // namespace

Command add_topic_type(CLI::App& topic) {
  auto o = std::make_shared<TypeOptions>();
  auto* cmd = topic.add_subcommand(
      "type", "Print a topic's type as IDL, from the type information on the domain (any topic, ours or not)");
  add_domain_option(cmd, o->domain);
  cmd->add_option("topic", o->name, "Topic name")->required();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to wait for an endpoint of a topic not in the catalogue")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer("Exit codes: 0 printed; 1 the type could not be had; 2 unknown topic.");
  return {cmd, [o](Context& ctx) { return run_topic_type(*o, ctx); }};
}

Command add_interface_show(CLI::App& interface) {
  auto o = std::make_shared<TypeOptions>();
  auto* cmd = interface.add_subcommand(
      "show", "Print a type as IDL: a catalogue type (NavGoal, autonomy::NavGoal) or the type of any topic on the domain");
  add_domain_option(cmd, o->domain);
  cmd->add_option("type", o->name, "Type name")->required();
  cmd->add_option("--discovery-wait", o->discovery_s, "Seconds to discover other processes' types")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->footer("Exit codes: 0 printed; 2 unknown type.");
  return {cmd, [o](Context& ctx) { return run_interface_show(*o, ctx); }};
}

}  // namespace autonomy::tools
