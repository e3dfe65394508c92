#pragma once
// The viewer's thin DDS shell: a participant like any other service that reads the world's
// topics (map, robot states, door truth, goals and their statuses, itineraries, radio links,
// courier job states) into a WorldView, and pushes frames to the web pages at most `rate_hz`
// times a second, only when something changed (and once a second regardless, so that a page
// sees the viewer is alive). Spacecraft telemetry and faults, executive status and the
// planner's latest plans go to the side panels (Panels), at most twice a second (read as CDR and
// walked with their type information, tools/xtypes: the panels show what `autonomy topic echo`
// prints); the executive's events, with the planner's plans and replies, go to its
// planned-against-executed timelines (ExecutionTraces), as often. It writes nothing but its
// heartbeat; it joins a running set at any time because every topic it reads for state is
// transient-local (a late joiner gets the last sample of each key), except goals, whose positions
// it learns from the next goal sent, and the executive's events (it shows what ran since).
//
// Foxglove clients (docs/viewer.md) are offered every topic of the catalogue as a channel, with
// its type's IDL (tools/recording); each subscription is a reader of its own, taking the samples
// as CDR (as on the wire) every 20 ms, made when the client subscribes (so it gets the topic's
// transient-local state at once) and deleted when it unsubscribes or leaves.
#include "common/dds/reader.hpp"
#include "common/dds/topics.hpp"
#include "common/service/service.hpp"
#include "services/viewer/core/execution_trace.hpp"
#include "services/viewer/core/latest_samples.hpp"
#include "services/viewer/core/panels.hpp"
#include "services/viewer/core/world_view.hpp"
#include "services/viewer/web/web_server.hpp"
#include "tools/recording/raw_topic.hpp"
#include "tools/xtypes/discovered_topic.hpp"

#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace autonomy::viewer {

struct ViewerNodeOptions {
  WebServerOptions web;
  double rate_hz = 10.0;  // frames per second at most
  WorldViewLimits limits;
};

class ViewerNode {
 public:
  ViewerNode(service::Service& service, ViewerNodeOptions options);
  ViewerNode(const ViewerNode&) = delete;
  ViewerNode& operator=(const ViewerNode&) = delete;

  // Where a browser on this host opens the viewer.
  std::string url() const;

 private:
  template <typename T>
  struct Subscription {
    Subscription(const dds::Participant& p, const dds::TopicSpec<T>& spec) : topic(p, spec), reader(p, topic) {}
    dds::Topic<T> topic;
    dds::Reader<T> reader;
  };
  // Every valid sample of the subscription applied to `sink` (the world view, or the executed
  // timelines).
  template <typename T, typename Sink>
  void follow(Subscription<T>& subscription, Sink& sink);
  // A side panel's topic (a catalogue topic): the latest sample of each key; a disposed or lost
  // one leaves.
  void follow_panel(const std::string& topic, const char* group);
  void push_frames();
  // Readers for the Foxglove subscriptions made or deleted as they come and go; their samples
  // sent.
  void pump_foxglove();

  service::Service& service_;
  ViewerNodeOptions options_;
  WorldView view_;
  Subscription<msg::WorldMap> map_;
  Subscription<msg::RobotState> robots_;
  Subscription<msg::DoorState> doors_;
  Subscription<msg::NavGoal> goals_;
  Subscription<msg::GoalStatus> goal_statuses_;
  Subscription<msg::Itinerary> itineraries_;
  Subscription<msg::RadioLink> links_;
  Subscription<msg::CourierJobStatus> jobs_;
  Panels panels_;
  // A panel topic's reader and its latest samples, walked when the panels are sent.
  struct PanelFeed {
    std::unique_ptr<xtypes::CdrReader> reader;
    LatestSamples latest;
    std::string topic;
  };
  std::vector<std::unique_ptr<PanelFeed>> panel_feeds_;
  Subscription<msg::LatestPlan> plans_;  // for the executed timelines
  ExecutionTraces execution_;
  Subscription<msg::ExecutiveEvent> executive_events_;
  Subscription<msg::PlanningReply> plan_replies_;  // every plan, also those the latest replaced
  std::vector<const recording::RecordableTopic*> foxglove_topics_;  // by channel id - 1
  std::unique_ptr<WebServer> server_;
  std::map<uint64_t, std::unique_ptr<recording::RawReader>> foxglove_readers_;  // by stream
  uint64_t foxglove_version_seen_ = 0;
  std::vector<recording::RawSample> foxglove_batch_;
  uint64_t map_version_sent_ = 0;
  uint64_t state_version_sent_ = 0;
  uint64_t panels_version_sent_ = 0;
  std::chrono::steady_clock::time_point last_panels_sent_{};
  uint64_t execution_version_sent_ = 0;
  std::chrono::steady_clock::time_point last_execution_sent_{};
  uint64_t frames_sent_ = 0;
  std::chrono::steady_clock::time_point last_state_sent_{};
};

}  // namespace autonomy::viewer
