#include "services/viewer/core/foxglove.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>

namespace autonomy::viewer::foxglove {

namespace {

bool foxglove_channel_known(const std::vector<Channel>& channels, uint32_t id) {
  return std::any_of(channels.begin(), channels.end(), [id](const Channel& c) { return c.id == id; });
}

// A JSON number that is a uint32 (ids of subscriptions and channels), or nothing.
bool foxglove_read_id(const nlohmann::json& v, uint32_t& out) {
  if (!v.is_number_integer() && !v.is_number_unsigned()) return false;
  if (v.is_number_unsigned()) {
    const auto u = v.get<uint64_t>();
    if (u > UINT32_MAX) return false;
    out = static_cast<uint32_t>(u);
    return true;
  }
  const auto i = v.get<int64_t>();
  if (i < 0 || i > static_cast<int64_t>(UINT32_MAX)) return false;
  out = static_cast<uint32_t>(i);
  return true;
}

}  // namespace

bool offers_subprotocol(std::string_view header) {
  size_t start = 0;
  while (start <= header.size()) {
    size_t end = header.find(',', start);
    if (end == std::string_view::npos) end = header.size();
    std::string_view token = header.substr(start, end - start);
    while (!token.empty() && std::isspace(static_cast<unsigned char>(token.front()))) token.remove_prefix(1);
    while (!token.empty() && std::isspace(static_cast<unsigned char>(token.back()))) token.remove_suffix(1);
    if (token == kSubprotocol) return true;
    start = end + 1;
  }
  return false;
}

std::string server_info(const std::string& name, const std::string& session_id) {
  return nlohmann::json{{"op", "serverInfo"},
                        {"name", name},
                        {"capabilities", nlohmann::json::array()},
                        {"sessionId", session_id}}
      .dump();
}

std::string advertise(const std::vector<Channel>& channels) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& c : channels) {
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", c.encoding},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", c.schema_encoding}});
  }
  return nlohmann::json{{"op", "advertise"}, {"channels", std::move(list)}}.dump();
}

std::string status(StatusLevel level, const std::string& message) {
  return nlohmann::json{{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}}.dump();
}

std::string message_data(uint32_t subscription_id, uint64_t receive_time_ns, std::string_view payload) {
  std::string frame;
  frame.reserve(1 + 4 + 8 + payload.size());
  frame.push_back('\x01');
  for (int i = 0; i < 4; ++i) frame.push_back(static_cast<char>((subscription_id >> (8 * i)) & 0xffu));
  for (int i = 0; i < 8; ++i) frame.push_back(static_cast<char>((receive_time_ns >> (8 * i)) & 0xffu));
  frame.append(payload);
  return frame;
}

Session::Session(const std::vector<Channel>& channels) : channels_(channels) {}

Session::Reply Session::on_text(std::string_view text) {
  Reply reply;
  auto refuse = [&reply](StatusLevel level, const std::string& why) { reply.texts.push_back(status(level, why)); };
  const nlohmann::json message = nlohmann::json::parse(text, nullptr, false);
  if (message.is_discarded() || !message.is_object() || !message.contains("op") || !message["op"].is_string()) {
    refuse(StatusLevel::Error, "not a JSON object with an \"op\" string");
    return reply;
  }
  const std::string op = message["op"].get<std::string>();
  if (op == "subscribe") {
    if (!message.contains("subscriptions") || !message["subscriptions"].is_array()) {
      refuse(StatusLevel::Error, "subscribe: no \"subscriptions\" array");
      return reply;
    }
    for (const auto& s : message["subscriptions"]) {
      uint32_t id = 0, channel = 0;
      if (!s.is_object() || !s.contains("id") || !s.contains("channelId") || !foxglove_read_id(s["id"], id) ||
          !foxglove_read_id(s["channelId"], channel)) {
        refuse(StatusLevel::Error, "subscribe: a subscription needs \"id\" and \"channelId\" (unsigned 32-bit)");
        continue;
      }
      if (!foxglove_channel_known(channels_, channel)) {
        refuse(StatusLevel::Error, "subscribe: no channel " + std::to_string(channel));
        continue;
      }
      if (channel_of_.count(id)) {
        refuse(StatusLevel::Error, "subscribe: subscription id " + std::to_string(id) + " is in use");
        continue;
      }
      const bool again = std::any_of(channel_of_.begin(), channel_of_.end(),
                                     [channel](const auto& kv) { return kv.second == channel; });
      if (again) {
        refuse(StatusLevel::Error, "subscribe: already subscribed to channel " + std::to_string(channel));
        continue;
      }
      channel_of_[id] = channel;
      reply.added.emplace_back(id, channel);
    }
  } else if (op == "unsubscribe") {
    if (!message.contains("subscriptionIds") || !message["subscriptionIds"].is_array()) {
      refuse(StatusLevel::Error, "unsubscribe: no \"subscriptionIds\" array");
      return reply;
    }
    for (const auto& v : message["subscriptionIds"]) {
      uint32_t id = 0;
      if (!foxglove_read_id(v, id) || channel_of_.erase(id) == 0) {
        refuse(StatusLevel::Warning, "unsubscribe: no subscription " + v.dump());
        continue;
      }
      reply.removed.push_back(id);
    }
  } else {
    refuse(StatusLevel::Error, "\"" + op + "\" is not offered by this server (it only streams DDS topics)");
  }
  return reply;
}

Session::Reply Session::on_binary() {
  Reply reply;
  reply.texts.push_back(status(StatusLevel::Error, "client publishing is not offered by this server"));
  return reply;
}

}  // namespace autonomy::viewer::foxglove
