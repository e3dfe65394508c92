#pragma once
// The subcommands of `autonomy`; each registers itself on its parent and returns what to run.
#include "tools/autonomy/common.hpp"

namespace autonomy::tools {

Command add_topic_list(CLI::App& topic);
Command add_topic_echo(CLI::App& topic);
Command add_topic_hz(CLI::App& topic);
Command add_topic_pub(CLI::App& topic);
Command add_topic_type(CLI::App& topic);
Command add_topic_info(CLI::App& topic);
Command add_topic_bw(CLI::App& topic);
Command add_interface_show(CLI::App& interface);
Command add_node_list(CLI::App& node);
Command add_node_info(CLI::App& node);
Command add_node_wait(CLI::App& node);
Command add_node_watch(CLI::App& node);
Command add_courier_send(CLI::App& courier);
Command add_courier_jobs(CLI::App& courier);
Command add_courier_cancel(CLI::App& courier);
Command add_courier_knowledge(CLI::App& courier);
Command add_plan(CLI::App& app);
Command add_record(CLI::App& app);
Command add_play(CLI::App& app);
Command add_replay(CLI::App& app);
Command add_bag_info(CLI::App& bag);

}  // namespace autonomy::tools
