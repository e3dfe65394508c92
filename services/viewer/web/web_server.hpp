#pragma once
// The viewer's HTTP + WebSocket server (Boost.Beast, on its own thread). It serves one page
// (GET /), the latest frames as plain JSON (GET /map.json, /state.json: for curl and scripts),
// and pushes frames to every WebSocket client of /ws. Pages that read slower than frames come
// get the newest one only: each connection holds at most one unsent frame of each kind (map,
// state, panels), a newer frame replaces the older unsent one (coalescing, so a slow page never
// makes the viewer buffer without bound). Beast stays inside web_server.cpp: it compiles in one file.
//
// A WebSocket client that offers the subprotocol foxglove.websocket.v1 (on any path) speaks the
// Foxglove WebSocket protocol instead (core/foxglove.hpp): it is told the server's channels and
// subscribes to them; the owner (the DDS node) asks which subscriptions exist (foxglove_streams)
// and sends each one its messages (send_foxglove).
#include "services/viewer/core/foxglove.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace autonomy::viewer {

// The kinds of frames, in the order a connection sends its unsent ones.
enum class FrameKind { Map = 0, State = 1, Panels = 2, Execution = 3 };
inline constexpr int kFrameKinds = 4;

struct WebServerOptions {
  std::string bind_address = "127.0.0.1";
  uint16_t port = 8080;  // 0: any free port (port() tells which)
};

// One Foxglove client's subscription to one channel. Stream ids are never reused by a server.
struct FoxgloveStream {
  uint64_t stream = 0;
  uint32_t channel = 0;
};

// Unsent Foxglove messages a client may hold (bytes); beyond, new messages to it are dropped.
inline constexpr std::size_t kFoxgloveMaxQueuedBytes = 8u << 20;

class WebServer {
 public:
  // Binds and starts serving at once. Throws std::runtime_error with a clear message when the
  // address is bad or the port is in use.
  // foxglove_channels: what Foxglove clients are offered (none: they are told there is nothing).
  WebServer(WebServerOptions options, std::string page_html, std::vector<foxglove::Channel> foxglove_channels = {});
  ~WebServer();  // closes every connection and joins the thread
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  uint16_t port() const;
  // Thread-safe. The newest frame of its kind (JSON text): sent to every connected page and to
  // pages that connect later.
  void publish(FrameKind kind, std::string json);
  // Pages connected over WebSocket now.
  std::size_t clients() const;
  // Frames not sent to a page because a newer one replaced them before it could be (all pages).
  uint64_t frames_coalesced() const;

  // Thread-safe. The Foxglove subscriptions now, and a number that changes whenever they do.
  std::vector<FoxgloveStream> foxglove_streams() const;
  uint64_t foxglove_version() const;
  // Thread-safe. One message (the CDR sample with its encapsulation header) for one
  // subscription, stamped with when it was received (ns since the epoch). Nothing happens when
  // the subscription has ended; dropped (and counted) when its client holds too much unsent.
  void send_foxglove(uint64_t stream, uint64_t receive_time_ns, std::string_view payload);
  std::size_t foxglove_clients() const;
  uint64_t foxglove_dropped() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace autonomy::viewer
