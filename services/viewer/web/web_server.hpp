#pragma once
// The viewer's HTTP + WebSocket server (Boost.Beast, on its own thread). It serves one page
// (GET /), the latest frames as plain JSON (GET /map.json, /state.json: for curl and scripts),
// and pushes frames to every WebSocket client of /ws. Pages that read slower than frames come
// get the newest one only: each connection holds at most one unsent frame of each kind (map,
// state, panels), a newer frame replaces the older unsent one (coalescing, so a slow page never
// makes the viewer buffer without bound). Beast stays inside web_server.cpp: it compiles in one file.
#include <cstdint>
#include <memory>
#include <string>

namespace autonomy::viewer {

// The kinds of frames, in the order a connection sends its unsent ones.
enum class FrameKind { Map = 0, State = 1, Panels = 2 };
inline constexpr int kFrameKinds = 3;

struct WebServerOptions {
  std::string bind_address = "127.0.0.1";
  uint16_t port = 8080;  // 0: any free port (port() tells which)
};

class WebServer {
 public:
  // Binds and starts serving at once. Throws std::runtime_error with a clear message when the
  // address is bad or the port is in use.
  WebServer(WebServerOptions options, std::string page_html);
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

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace autonomy::viewer
