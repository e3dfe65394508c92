#pragma once
// The Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1,
// https://github.com/foxglove/ws-protocol/blob/main/docs/spec.md), the part a DDS viewer needs:
// the server's JSON messages (serverInfo, advertise, status), the binary Message Data frame, and a
// connection's subscriptions (subscribe / unsubscribe, checked against the advertised channels).
// Pure logic: the WebSocket itself is in web/web_server.cpp, the DDS readers in dds/.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace autonomy::viewer::foxglove {

inline constexpr std::string_view kSubprotocol = "foxglove.websocket.v1";

// One DDS topic as a Foxglove channel: encoding "cdr" (the sample as on the wire, with its
// 4-byte encapsulation header), schema the type's OMG IDL text (schemaEncoding "omgidl").
struct Channel {
  uint32_t id = 0;
  std::string topic;            // "autonomy/robot/state"
  std::string encoding;         // "cdr"
  std::string schema_name;      // "autonomy::RobotState"
  std::string schema;           // self-contained IDL text
  std::string schema_encoding;  // "omgidl"
};

// True when a Sec-WebSocket-Protocol request header ("a, b") offers foxglove.websocket.v1.
bool offers_subprotocol(std::string_view header);

std::string server_info(const std::string& name, const std::string& session_id);
std::string advertise(const std::vector<Channel>& channels);
enum class StatusLevel { Info = 0, Warning = 1, Error = 2 };
std::string status(StatusLevel level, const std::string& message);
// Opcode 0x01, subscription id (u32 LE), receive time (u64 LE, ns), payload.
std::string message_data(uint32_t subscription_id, uint64_t receive_time_ns, std::string_view payload);

// One connection's subscriptions. A client message in, what changed and what to answer out.
class Session {
 public:
  explicit Session(const std::vector<Channel>& channels);

  struct Reply {
    std::vector<std::pair<uint32_t, uint32_t>> added;  // (subscription id, channel id)
    std::vector<uint32_t> removed;                     // subscription ids
    std::vector<std::string> texts;                    // status messages for the client
  };
  // A text message from the client. Subscriptions to unknown channels, a subscription id in use,
  // a second subscription to one channel, unknown subscription ids in unsubscribe, operations
  // this server does not offer (client publishing, parameters, services) and malformed JSON are
  // answered with a status message (warning or error) and change nothing else.
  Reply on_text(std::string_view text);
  // A binary message from the client: client publishing is not offered.
  Reply on_binary();

  const std::map<uint32_t, uint32_t>& subscriptions() const { return channel_of_; }  // id -> channel

 private:
  const std::vector<Channel>& channels_;
  std::map<uint32_t, uint32_t> channel_of_;
};

}  // namespace autonomy::viewer::foxglove
