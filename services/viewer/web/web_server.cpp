#include "services/viewer/web/web_server.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace autonomy::viewer {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Frame = std::shared_ptr<const std::string>;

namespace {

// Counters shared by the server and its connections; they outlive every connection.
struct ViewerWebCounters {
  std::atomic<std::size_t> clients{0};
  std::atomic<uint64_t> coalesced{0};
};

using ViewerFrames = std::array<Frame, kFrameKinds>;  // by FrameKind; empty: none yet

// One page's WebSocket: at most one unsent frame of each kind, the map first.
class ViewerWebSocket : public std::enable_shared_from_this<ViewerWebSocket> {
 public:
  ViewerWebSocket(tcp::socket socket, ViewerWebCounters& counters) : ws_(std::move(socket)), counters_(counters) {}
  ~ViewerWebSocket() {
    if (accepted_) --counters_.clients;
  }

  // Accepts the upgrade request; then sends the newest frames (those known now, or newer ones
  // offered while the handshake runs) and keeps the page current.
  void accept(http::request<http::string_body> request, const ViewerFrames& latest) {
    for (int k = 0; k < kFrameKinds; ++k)
      if (latest[k]) pending_[k] = latest[k];
    upgrade_ = std::move(request);
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.set_option(websocket::stream_base::decorator(
        [](websocket::response_type& res) { res.set(http::field::server, "autonomy-viewer"); }));
    ws_.async_accept(upgrade_, [self = shared_from_this()](beast::error_code ec) {
      if (ec) {
        self->closed_ = true;
        return;
      }
      self->accepted_ = true;
      ++self->counters_.clients;
      self->write_next();
      self->read_next();
    });
  }

  // Called on the server's thread for every new frame.
  void offer(FrameKind kind, Frame frame) {
    if (closed_) return;
    std::optional<Frame>& slot = pending_[static_cast<int>(kind)];
    if (slot) ++counters_.coalesced;
    slot = std::move(frame);
    if (accepted_ && !writing_) write_next();
  }

 private:
  void write_next() {
    auto slot_it = std::find_if(pending_.begin(), pending_.end(), [](const auto& p) { return p.has_value(); });
    if (slot_it == pending_.end()) return;
    std::optional<Frame>& slot = *slot_it;
    Frame frame = std::move(*slot);
    slot.reset();
    writing_ = true;
    ws_.text(true);
    ws_.async_write(asio::buffer(*frame), [self = shared_from_this(), frame](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      if (ec) {
        self->closed_ = true;
        return;
      }
      self->write_next();
    });
  }

  // Pages send nothing the viewer needs yet; reading keeps the connection's close and pings seen.
  void read_next() {
    ws_.async_read(incoming_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) {
        self->closed_ = true;
        return;
      }
      self->incoming_.consume(self->incoming_.size());
      self->read_next();
    });
  }

  websocket::stream<beast::tcp_stream> ws_;
  ViewerWebCounters& counters_;
  beast::flat_buffer incoming_;
  http::request<http::string_body> upgrade_;
  std::array<std::optional<Frame>, kFrameKinds> pending_;  // by FrameKind
  bool accepted_ = false;
  bool writing_ = false;
  bool closed_ = false;
};

}  // namespace

struct WebServer::Impl {
  ViewerWebCounters counters;  // first: connections destroyed with the io_context still count
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::string page;
  ViewerFrames latest;  // only touched on the server's thread
  std::vector<std::weak_ptr<ViewerWebSocket>> sockets;
  std::thread thread;

  void accept_next() {
    acceptor.async_accept([this](beast::error_code ec, tcp::socket socket) {
      if (ec) {
        if (ec != asio::error::operation_aborted) spdlog::warn("viewer: accept failed: {}", ec.message());
        if (!acceptor.is_open()) return;
      } else {
        std::make_shared<HttpConnection>(*this, std::move(socket))->read_request();
      }
      accept_next();
    });
  }

  void broadcast(FrameKind kind, Frame frame) {
    latest[static_cast<int>(kind)] = frame;
    std::vector<std::weak_ptr<ViewerWebSocket>> alive;
    alive.reserve(sockets.size());
    for (auto& weak : sockets) {
      if (auto s = weak.lock()) {
        s->offer(kind, frame);
        alive.push_back(std::move(weak));
      }
    }
    sockets.swap(alive);
  }

  // One HTTP connection: serves the page and the JSON frames, or hands itself over to a
  // WebSocket on GET /ws.
  class HttpConnection : public std::enable_shared_from_this<HttpConnection> {
   public:
    HttpConnection(Impl& server, tcp::socket socket) : server_(server), stream_(std::move(socket)) {}

    void read_request() {
      request_ = {};
      stream_.expires_after(std::chrono::seconds(30));
      http::async_read(stream_, buffer_, request_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
        if (ec) return;  // closed, timed out or malformed: nothing to answer
        self->answer();
      });
    }

   private:
    void answer() {
      const std::string target(request_.target());
      if (websocket::is_upgrade(request_) && target == "/ws") {
        stream_.expires_never();
        auto ws = std::make_shared<ViewerWebSocket>(stream_.release_socket(), server_.counters);
        server_.sockets.push_back(ws);
        ws->accept(std::move(request_), server_.latest);
        return;
      }
      auto response = std::make_shared<http::response<http::string_body>>();
      response->version(request_.version());
      response->keep_alive(request_.keep_alive());
      response->set(http::field::server, "autonomy-viewer");
      response->set(http::field::cache_control, "no-store");
      if (request_.method() != http::verb::get && request_.method() != http::verb::head) {
        response->result(http::status::method_not_allowed);
        response->set(http::field::content_type, "text/plain");
        response->body() = "only GET\n";
      } else if (target == "/" || target == "/index.html") {
        response->result(http::status::ok);
        response->set(http::field::content_type, "text/html; charset=utf-8");
        response->body() = server_.page;
      } else if (target == "/map.json" || target == "/state.json" || target == "/panels.json") {
        const FrameKind kind = target == "/map.json"     ? FrameKind::Map
                               : target == "/state.json" ? FrameKind::State
                                                         : FrameKind::Panels;
        const Frame& frame = server_.latest[static_cast<int>(kind)];
        response->result(frame ? http::status::ok : http::status::service_unavailable);
        response->set(http::field::content_type, "application/json");
        response->body() = frame ? *frame : std::string("{\"error\":\"nothing heard yet\"}");
      } else {
        response->result(http::status::not_found);
        response->set(http::field::content_type, "text/plain");
        response->body() = "not found: " + target + "\n";
      }
      if (request_.method() == http::verb::head) response->body().clear();
      response->prepare_payload();
      http::async_write(stream_, *response,
                        [self = shared_from_this(), response](beast::error_code ec, std::size_t) {
                          if (ec || !response->keep_alive()) {
                            beast::error_code ignored;
                            self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                            return;
                          }
                          self->read_request();
                        });
    }

    Impl& server_;
    beast::tcp_stream stream_;
    beast::flat_buffer buffer_;
    http::request<http::string_body> request_;
  };
};

WebServer::WebServer(WebServerOptions options, std::string page_html) : impl_(std::make_unique<Impl>()) {
  impl_->page = std::move(page_html);
  beast::error_code ec;
  const auto address = asio::ip::make_address(options.bind_address, ec);
  if (ec) throw std::runtime_error("viewer: bad --bind address \"" + options.bind_address + "\": " + ec.message());
  const tcp::endpoint endpoint(address, options.port);
  auto& acceptor = impl_->acceptor;
  acceptor.open(endpoint.protocol(), ec);
  if (!ec) acceptor.set_option(asio::socket_base::reuse_address(true), ec);
  if (!ec) acceptor.bind(endpoint, ec);
  if (ec == asio::error::address_in_use) {
    throw std::runtime_error("viewer: port " + std::to_string(options.port) + " on " + options.bind_address +
                             " is in use (another viewer?); choose another with --port, or --port 0 for any free one");
  }
  if (ec == asio::error::access_denied) {
    throw std::runtime_error("viewer: not allowed to listen on port " + std::to_string(options.port) +
                             " (ports below 1024 need privileges); choose another with --port");
  }
  if (!ec) acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) {
    throw std::runtime_error("viewer: cannot listen on " + options.bind_address + ":" + std::to_string(options.port) +
                             ": " + ec.message());
  }
  impl_->accept_next();
  impl_->thread = std::thread([this] { impl_->io.run(); });
}

WebServer::~WebServer() {
  impl_->io.stop();
  if (impl_->thread.joinable()) impl_->thread.join();
}

uint16_t WebServer::port() const { return impl_->acceptor.local_endpoint().port(); }

void WebServer::publish(FrameKind kind, std::string json) {
  auto frame = std::make_shared<const std::string>(std::move(json));
  asio::post(impl_->io, [impl = impl_.get(), kind, frame] { impl->broadcast(kind, frame); });
}

std::size_t WebServer::clients() const { return impl_->counters.clients.load(); }
uint64_t WebServer::frames_coalesced() const { return impl_->counters.coalesced.load(); }

}  // namespace autonomy::viewer
