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
#include <chrono>
#include <deque>
#include <map>
#include <mutex>
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
  std::atomic<std::size_t> foxglove_clients{0};
  std::atomic<uint64_t> foxglove_dropped{0};
};

class ViewerFoxgloveSocket;

// Every Foxglove subscription of every client, by stream id: written on the server's thread,
// read by the DDS node's thread (which streams exist; where a message goes).
struct ViewerFoxgloveRegistry {
  struct Entry {
    std::weak_ptr<ViewerFoxgloveSocket> socket;
    uint32_t subscription = 0;
    uint32_t channel = 0;
  };
  mutable std::mutex mutex;
  std::map<uint64_t, Entry> streams;
  uint64_t next_stream = 1;
  std::atomic<uint64_t> version{0};

  uint64_t add(std::weak_ptr<ViewerFoxgloveSocket> socket, uint32_t subscription, uint32_t channel) {
    std::lock_guard lock(mutex);
    const uint64_t id = next_stream++;
    streams[id] = {std::move(socket), subscription, channel};
    ++version;
    return id;
  }
  void remove(uint64_t stream) {
    std::lock_guard lock(mutex);
    if (streams.erase(stream)) ++version;
  }
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

// One Foxglove client (subprotocol foxglove.websocket.v1): serverInfo and advertise first, then
// its subscriptions' messages in order, each queued until written. A client that reads slower
// than messages come loses the newest ones past kFoxgloveMaxQueuedBytes unsent (counted), so a
// stalled client never makes the viewer buffer without bound; status messages are never dropped.
class ViewerFoxgloveSocket : public std::enable_shared_from_this<ViewerFoxgloveSocket> {
 public:
  ViewerFoxgloveSocket(tcp::socket socket, ViewerWebCounters& counters, ViewerFoxgloveRegistry& registry,
                       const std::vector<foxglove::Channel>& channels)
      : ws_(std::move(socket)), counters_(counters), registry_(registry), session_(channels) {}
  ~ViewerFoxgloveSocket() {
    release_streams();
    if (accepted_) --counters_.foxglove_clients;
  }

  void accept(http::request<http::string_body> request, Frame server_info, Frame advertise) {
    upgrade_ = std::move(request);
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.set_option(websocket::stream_base::decorator([](websocket::response_type& res) {
      res.set(http::field::server, "autonomy-viewer");
      res.set(http::field::sec_websocket_protocol, std::string(foxglove::kSubprotocol));
    }));
    ws_.async_accept(upgrade_, [self = shared_from_this(), server_info, advertise](beast::error_code ec) {
      if (ec) {
        self->closed_ = true;
        return;
      }
      self->accepted_ = true;
      ++self->counters_.foxglove_clients;
      self->queue(false, server_info);
      self->queue(false, advertise);
      self->read_next();
    });
  }

  // On the server's thread: a text (JSON) or binary message for this client.
  void queue(bool binary, Frame frame) {
    if (closed_) return;
    if (binary && queued_bytes_ + frame->size() > kFoxgloveMaxQueuedBytes) {
      ++counters_.foxglove_dropped;
      return;
    }
    queued_bytes_ += frame->size();
    outgoing_.emplace_back(binary, std::move(frame));
    if (accepted_ && !writing_) write_next();
  }

 private:
  void write_next() {
    if (outgoing_.empty() || closed_) return;
    std::pair<bool, Frame> next = std::move(outgoing_.front());
    outgoing_.pop_front();
    Frame frame = std::move(next.second);
    writing_ = true;
    ws_.binary(next.first);
    ws_.async_write(asio::buffer(*frame), [self = shared_from_this(), frame](beast::error_code ec, std::size_t) {
      self->writing_ = false;
      self->queued_bytes_ -= frame->size();
      if (ec) {
        self->close();
        return;
      }
      self->write_next();
    });
  }

  void read_next() {
    ws_.async_read(incoming_, [self = shared_from_this()](beast::error_code ec, std::size_t) {
      if (ec) {
        self->close();
        return;
      }
      const auto reply = self->ws_.got_text() ? self->session_.on_text(beast::buffers_to_string(self->incoming_.data()))
                                              : self->session_.on_binary();
      self->incoming_.consume(self->incoming_.size());
      for (const auto& [subscription, channel] : reply.added)
        self->stream_of_[subscription] = self->registry_.add(self->weak_from_this(), subscription, channel);
      for (const uint32_t subscription : reply.removed) {
        const auto it = self->stream_of_.find(subscription);
        if (it == self->stream_of_.end()) continue;
        self->registry_.remove(it->second);
        self->stream_of_.erase(it);
      }
      for (const auto& text : reply.texts) self->queue(false, std::make_shared<const std::string>(text));
      self->read_next();
    });
  }

  void close() {
    closed_ = true;
    for (const auto& unsent : outgoing_) queued_bytes_ -= unsent.second->size();
    outgoing_.clear();
    release_streams();
  }

  void release_streams() {
    for (const auto& [subscription, stream] : stream_of_) registry_.remove(stream);
    stream_of_.clear();
  }

  websocket::stream<beast::tcp_stream> ws_;
  ViewerWebCounters& counters_;
  ViewerFoxgloveRegistry& registry_;
  foxglove::Session session_;
  beast::flat_buffer incoming_;
  http::request<http::string_body> upgrade_;
  std::deque<std::pair<bool, Frame>> outgoing_;  // (binary, frame), oldest first
  std::size_t queued_bytes_ = 0;                  // outgoing_ and the frame being written
  std::map<uint32_t, uint64_t> stream_of_;        // subscription id -> stream id
  bool accepted_ = false;
  bool writing_ = false;
  bool closed_ = false;
};

}  // namespace

struct WebServer::Impl {
  ViewerWebCounters counters;  // first: connections destroyed with the io_context still count
  ViewerFoxgloveRegistry foxglove_registry;  // and release their Foxglove streams
  asio::io_context io;
  tcp::acceptor acceptor{io};
  std::string page;
  std::vector<foxglove::Channel> channels;
  Frame server_info, advertise;  // what every Foxglove client is sent first
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
      const auto offered = request_[http::field::sec_websocket_protocol];
      if (websocket::is_upgrade(request_) &&
          foxglove::offers_subprotocol(std::string_view(offered.data(), offered.size()))) {
        stream_.expires_never();
        auto ws = std::make_shared<ViewerFoxgloveSocket>(stream_.release_socket(), server_.counters,
                                                         server_.foxglove_registry, server_.channels);
        ws->accept(std::move(request_), server_.server_info, server_.advertise);
        return;
      }
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
      } else if (target == "/map.json" || target == "/state.json" || target == "/panels.json" ||
                 target == "/execution.json") {
        const FrameKind kind = target == "/map.json"      ? FrameKind::Map
                               : target == "/state.json"  ? FrameKind::State
                               : target == "/panels.json" ? FrameKind::Panels
                                                          : FrameKind::Execution;
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

WebServer::WebServer(WebServerOptions options, std::string page_html, std::vector<foxglove::Channel> foxglove_channels)
    : impl_(std::make_unique<Impl>()) {
  impl_->page = std::move(page_html);
  impl_->channels = std::move(foxglove_channels);
  const auto started = std::chrono::system_clock::now().time_since_epoch();
  impl_->server_info = std::make_shared<const std::string>(foxglove::server_info(
      "autonomy viewer", std::to_string(std::chrono::duration_cast<std::chrono::nanoseconds>(started).count())));
  impl_->advertise = std::make_shared<const std::string>(foxglove::advertise(impl_->channels));
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

std::vector<FoxgloveStream> WebServer::foxglove_streams() const {
  std::lock_guard lock(impl_->foxglove_registry.mutex);
  std::vector<FoxgloveStream> out;
  out.reserve(impl_->foxglove_registry.streams.size());
  for (const auto& [id, entry] : impl_->foxglove_registry.streams) out.push_back({id, entry.channel});
  return out;
}

uint64_t WebServer::foxglove_version() const { return impl_->foxglove_registry.version.load(); }

void WebServer::send_foxglove(uint64_t stream, uint64_t receive_time_ns, std::string_view payload) {
  std::weak_ptr<ViewerFoxgloveSocket> socket;
  uint32_t subscription = 0;
  {
    std::lock_guard lock(impl_->foxglove_registry.mutex);
    const auto it = impl_->foxglove_registry.streams.find(stream);
    if (it == impl_->foxglove_registry.streams.end()) return;
    socket = it->second.socket;
    subscription = it->second.subscription;
  }
  auto frame = std::make_shared<const std::string>(foxglove::message_data(subscription, receive_time_ns, payload));
  asio::post(impl_->io, [socket = std::move(socket), frame = std::move(frame)] {
    if (auto s = socket.lock()) s->queue(true, frame);
  });
}

std::size_t WebServer::foxglove_clients() const { return impl_->counters.foxglove_clients.load(); }
uint64_t WebServer::foxglove_dropped() const { return impl_->counters.foxglove_dropped.load(); }

}  // namespace autonomy::viewer
