// The Foxglove WebSocket protocol's messages and a connection's subscriptions.
#include "services/viewer/core/foxglove.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace autonomy::viewer::foxglove {
namespace {

std::vector<Channel> foxglove_test_channels() {
  return {{1, "autonomy/robot/state", "cdr", "autonomy::RobotState",
           "module autonomy { struct RobotState { string robot_id; }; };", "omgidl"},
          {2, "autonomy/map", "cdr", "autonomy::WorldMap", "module autonomy { struct WorldMap { string name; }; };",
           "omgidl"}};
}

nlohmann::json foxglove_only_text(const Session::Reply& reply) {
  EXPECT_EQ(reply.texts.size(), 1u);
  return reply.texts.empty() ? nlohmann::json() : nlohmann::json::parse(reply.texts[0]);
}

TEST(FoxgloveTest, SubprotocolIsFoundAmongOthers) {
  EXPECT_TRUE(offers_subprotocol("foxglove.websocket.v1"));
  EXPECT_TRUE(offers_subprotocol("foxglove.sdk.v1, foxglove.websocket.v1"));
  EXPECT_TRUE(offers_subprotocol(" foxglove.websocket.v1 ,x"));
  EXPECT_FALSE(offers_subprotocol(""));
  EXPECT_FALSE(offers_subprotocol("foxglove.websocket.v10"));
  EXPECT_FALSE(offers_subprotocol("chat, superchat"));
}

TEST(FoxgloveTest, ServerInfoAndAdvertiseCarryTheChannelsAndTheirIdlSchemas) {
  const auto info = nlohmann::json::parse(server_info("autonomy viewer", "123"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["name"], "autonomy viewer");
  EXPECT_TRUE(info["capabilities"].is_array() && info["capabilities"].empty());
  EXPECT_EQ(info["sessionId"], "123");

  const auto channels = foxglove_test_channels();
  const auto adv = nlohmann::json::parse(advertise(channels));
  EXPECT_EQ(adv["op"], "advertise");
  ASSERT_EQ(adv["channels"].size(), 2u);
  const auto& c = adv["channels"][0];
  EXPECT_EQ(c["id"], 1);
  EXPECT_EQ(c["topic"], "autonomy/robot/state");
  EXPECT_EQ(c["encoding"], "cdr");
  EXPECT_EQ(c["schemaName"], "autonomy::RobotState");
  EXPECT_EQ(c["schemaEncoding"], "omgidl");
  EXPECT_EQ(c["schema"], channels[0].schema);  // IDL as plain text, not base64
}

TEST(FoxgloveTest, MessageDataIsOpcodeSubscriptionTimeAndPayloadLittleEndian) {
  const std::string payload("\x00\x01\x00\x00xyz", 7);
  const std::string frame = message_data(0x04030201u, 0x0c0b0a0908070605ull, payload);
  ASSERT_EQ(frame.size(), 1u + 4u + 8u + payload.size());
  EXPECT_EQ(frame[0], '\x01');
  for (int i = 0; i < 12; ++i) EXPECT_EQ(static_cast<unsigned char>(frame[1 + i]), i + 1) << i;
  EXPECT_EQ(frame.substr(13), payload);
}

TEST(FoxgloveTest, SubscribeAndUnsubscribeKeepTheConnectionsSubscriptions) {
  const auto channels = foxglove_test_channels();
  Session session(channels);
  auto r = session.on_text(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":1},{"id":7,"channelId":2}]})");
  EXPECT_TRUE(r.texts.empty());
  ASSERT_EQ(r.added.size(), 2u);
  EXPECT_EQ(r.added[0], (std::pair<uint32_t, uint32_t>{0, 1}));
  EXPECT_EQ(r.added[1], (std::pair<uint32_t, uint32_t>{7, 2}));
  EXPECT_EQ(session.subscriptions().size(), 2u);

  r = session.on_text(R"({"op":"unsubscribe","subscriptionIds":[7]})");
  EXPECT_TRUE(r.texts.empty());
  EXPECT_EQ(r.removed, std::vector<uint32_t>{7});
  EXPECT_EQ(session.subscriptions(), (std::map<uint32_t, uint32_t>{{0, 1}}));

  // After unsubscribing, the id may be used again.
  r = session.on_text(R"({"op":"subscribe","subscriptions":[{"id":7,"channelId":2}]})");
  EXPECT_EQ(r.added.size(), 1u);
}

TEST(FoxgloveTest, BadRequestsAreAnsweredWithAStatusAndChangeNothing) {
  const auto channels = foxglove_test_channels();
  Session session(channels);
  ASSERT_EQ(session.on_text(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})").added.size(), 1u);

  auto expect_refused = [&](const std::string& text, int level, const std::string& says) {
    const auto r = session.on_text(text);
    EXPECT_TRUE(r.added.empty()) << text;
    EXPECT_TRUE(r.removed.empty()) << text;
    const auto s = foxglove_only_text(r);
    EXPECT_EQ(s["op"], "status") << text;
    EXPECT_EQ(s["level"], level) << text;
    EXPECT_NE(s["message"].get<std::string>().find(says), std::string::npos) << s.dump();
  };
  expect_refused(R"({"op":"subscribe","subscriptions":[{"id":2,"channelId":99}]})", 2, "no channel 99");
  expect_refused(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":2}]})", 2, "id 1 is in use");
  expect_refused(R"({"op":"subscribe","subscriptions":[{"id":3,"channelId":1}]})", 2,
                 "already subscribed to channel 1");
  expect_refused(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":2}]})", 2, "unsigned 32-bit");
  expect_refused(R"({"op":"unsubscribe","subscriptionIds":[5]})", 1, "no subscription 5");
  expect_refused(R"({"op":"getParameters","parameterNames":[]})", 2, "\"getParameters\" is not offered");
  expect_refused("not json", 2, "not a JSON object");
  const auto binary = session.on_binary();
  EXPECT_EQ(foxglove_only_text(binary)["level"], 2);
  EXPECT_EQ(session.subscriptions(), (std::map<uint32_t, uint32_t>{{1, 1}}));
}

}  // namespace
}  // namespace autonomy::viewer::foxglove
