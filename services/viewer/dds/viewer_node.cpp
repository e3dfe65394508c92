#include "services/viewer/dds/viewer_node.hpp"

#include "services/viewer/core/frames.hpp"
#include "services/viewer/web/page.hpp"
#include "tools/recording/idl_text.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>

namespace autonomy::viewer {

namespace {

// A robot whose state instance is disposed (the simulator removed it or stopped) or lost its
// writer leaves the picture; other topics keep their last value (a closed door stays closed).
bool viewer_instance_gone(dds::InstanceState s) { return s != dds::InstanceState::Alive; }

}  // namespace

ViewerNode::ViewerNode(service::Service& service, ViewerNodeOptions options)
    : service_(service),
      options_(std::move(options)),
      view_(options_.limits),
      map_(service.participant(), dds::topics::world_map),
      robots_(service.participant(), dds::topics::robot_state),
      doors_(service.participant(), dds::topics::truth_door),
      goals_(service.participant(), dds::topics::nav_goal),
      goal_statuses_(service.participant(), dds::topics::goal_status),
      itineraries_(service.participant(), dds::topics::itinerary),
      links_(service.participant(), dds::topics::radio_link),
      jobs_(service.participant(), dds::topics::courier_job_status),
      plans_(service.participant(), dds::topics::planner_plan),
      executive_events_(service.participant(), dds::topics::executive_event),
      plan_replies_(service.participant(), dds::topics::planner_reply) {
  if (!(options_.rate_hz > 0.0 && options_.rate_hz <= 100.0))
    throw std::invalid_argument("viewer: --rate must be in (0, 100] frames per second");
  // Every catalogue topic as a Foxglove channel: CDR samples, the type's self-contained IDL.
  std::vector<foxglove::Channel> channels;
  for (const auto& topic : recording::recordable_topics()) {
    foxglove::Channel c;
    try {
      c.schema = recording::omgidl_schema(topic.type_name);
    } catch (const std::exception& e) {
      spdlog::warn("viewer: topic {} is not offered to Foxglove clients: {}", topic.name, e.what());
      continue;
    }
    foxglove_topics_.push_back(&topic);
    c.id = static_cast<uint32_t>(foxglove_topics_.size());
    c.topic = topic.name;
    c.encoding = "cdr";
    c.schema_name = topic.type_name;
    c.schema_encoding = "omgidl";
    channels.push_back(std::move(c));
  }
  server_ = std::make_unique<WebServer>(options_.web, std::string(viewer_page_html()), std::move(channels));

  auto& loop = service.loop();
  follow(map_, view_);
  loop.on_samples<msg::RobotState>(robots_.reader, [this](std::vector<dds::Sample<msg::RobotState>> samples) {
    for (const auto& s : samples) {
      if (viewer_instance_gone(s.instance_state))
        view_.remove_robot(s.value.robot_id);
      else if (s.valid)
        view_.apply(s.value);
    }
  });
  follow(doors_, view_);
  follow(goals_, view_);
  follow(goal_statuses_, view_);
  follow(itineraries_, view_);
  follow(links_, view_);
  follow(jobs_, view_);
  follow_panel(dds::topics::spacecraft_telemetry.name, "spacecraft");
  follow_panel(dds::topics::truth_spacecraft_fault.name, "faults");
  follow_panel(dds::topics::executive_status.name, "executive");
  follow_panel(dds::topics::planner_plan.name, "plans");
  // A plan also goes to the executed timelines (a disposed one stays there: its executive may
  // still run it).
  follow(plans_, execution_);
  follow(plan_replies_, execution_);
  follow(executive_events_, execution_);
  const auto period = std::chrono::nanoseconds(static_cast<int64_t>(1e9 / options_.rate_hz));
  loop.every(period, [this] { push_frames(); });
  loop.every(std::chrono::milliseconds(20), [this] { pump_foxglove(); });

  service.heartbeat().set_detail(url());
  service.set_ready();
  const std::string ws_url = "ws" + url().substr(4);  // http://... -> ws://...
  spdlog::info("viewer: open {} in a browser (frames on the WebSocket {}ws; Foxglove clients: {}, {} channels)", url(),
               ws_url, ws_url, foxglove_topics_.size());
  // On stdout too, for scripts that start the viewer and print its address.
  std::printf("viewer: open %s\n", url().c_str());
  std::fflush(stdout);
}

template <typename T, typename Sink>
void ViewerNode::follow(Subscription<T>& subscription, Sink& sink) {
  service_.loop().on_samples<T>(subscription.reader, [&sink](std::vector<dds::Sample<T>> samples) {
    for (const auto& s : samples)
      if (s.valid) sink.apply(s.value);
  });
}

void ViewerNode::follow_panel(const std::string& topic, const char* group) {
  const recording::RecordableTopic* ours = recording::find_recordable(topic);
  if (!ours) throw std::logic_error("viewer: panel topic " + topic + " is not in the catalogue");
  const auto& participant = service_.participant();
  const xtypes::DiscoveredTopic typed = xtypes::compiled_topic(participant.handle(), ours->name, ours->descriptor);
  auto feed = std::make_unique<PanelFeed>(PanelFeed{
      std::make_unique<xtypes::CdrReader>(participant.handle(), typed, dds::make_qos(ours->qos).get()),
      LatestSamples(typed.type, group), typed.name});
  PanelFeed* f = feed.get();
  panel_feeds_.push_back(std::move(feed));
  service_.loop().on_condition(f->reader->data_condition(), [f] {
    for (auto& s : f->reader->take()) {
      const bool alive = s.instance_state == DDS_IST_ALIVE;
      if (s.valid && alive)
        f->latest.add(s.instance, true, std::move(s.cdr));
      else if (!alive)  // disposed, or its writers gone: the panel leaves
        f->latest.add(s.instance, false, {});
    }
  });
}

std::string ViewerNode::url() const {
  const std::string host = options_.web.bind_address == "0.0.0.0" ? service::host_name() : options_.web.bind_address;
  return "http://" + host + ":" + std::to_string(server_->port()) + "/";
}

void ViewerNode::pump_foxglove() {
  const uint64_t version = server_->foxglove_version();
  if (version != foxglove_version_seen_) {
    foxglove_version_seen_ = version;  // read before the streams: a change in between is seen next time
    const auto streams = server_->foxglove_streams();
    for (auto it = foxglove_readers_.begin(); it != foxglove_readers_.end();) {
      const bool kept =
          std::any_of(streams.begin(), streams.end(), [&](const FoxgloveStream& s) { return s.stream == it->first; });
      it = kept ? std::next(it) : foxglove_readers_.erase(it);
    }
    for (const auto& s : streams) {
      if (foxglove_readers_.count(s.stream) || s.channel == 0 || s.channel > foxglove_topics_.size()) continue;
      foxglove_readers_.emplace(
          s.stream, std::make_unique<recording::RawReader>(service_.participant(), *foxglove_topics_[s.channel - 1]));
    }
  }
  for (auto& [stream, reader] : foxglove_readers_) {
    foxglove_batch_.clear();
    reader->take(foxglove_batch_);
    for (const auto& sample : foxglove_batch_)
      server_->send_foxglove(stream, static_cast<uint64_t>(sample.reception_time), sample.cdr);
  }
}

void ViewerNode::push_frames() {
  if (view_.map_version() != map_version_sent_) {
    map_version_sent_ = view_.map_version();
    server_->publish(FrameKind::Map, map_frame(view_).dump());
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - last_panels_sent_ >= std::chrono::milliseconds(500)) {
    for (auto& feed : panel_feeds_)
      for (const auto& error : feed->latest.flush(panels_))
        spdlog::warn("viewer: a sample of {} does not fit its type: {}", feed->topic, error);
    if (panels_.version() != panels_version_sent_) {
      panels_version_sent_ = panels_.version();
      last_panels_sent_ = now;
      server_->publish(FrameKind::Panels, panels_.frame().dump());
    }
  }
  if (execution_.version() != execution_version_sent_ && now - last_execution_sent_ >= std::chrono::milliseconds(500)) {
    execution_version_sent_ = execution_.version();
    last_execution_sent_ = now;
    server_->publish(FrameKind::Execution, execution_frame(execution_).dump());
  }
  const bool changed = view_.state_version() != state_version_sent_;
  if (!changed && now - last_state_sent_ < std::chrono::seconds(1)) return;
  state_version_sent_ = view_.state_version();
  last_state_sent_ = now;
  server_->publish(FrameKind::State, state_frame(view_, ++frames_sent_).dump());
}

}  // namespace autonomy::viewer
