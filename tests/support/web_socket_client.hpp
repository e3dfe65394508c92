#pragma once
// A minimal WebSocket client for tests of the viewer (RFC 6455, client side, text frames from
// the server only): connects to 127.0.0.1:port, upgrades GET `path`, then returns one message
// at a time with a timeout. It sends nothing after the handshake (a client's frames would need
// masking); closing the socket ends the session. Also a one-shot HTTP GET. No Boost: the
// viewer compiles Beast in one file only, tests do not pay for it again.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace autonomy::test {

class WebSocketClient {
 public:
  using Clock = std::chrono::steady_clock;

  WebSocketClient(uint16_t port, const std::string& path) : fd_(connect_to(port)) {
    send_all("GET " + path +
             " HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
             "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    std::size_t end;
    while ((end = buffer_.find("\r\n\r\n")) == std::string::npos) fill(deadline);
    const std::string head = buffer_.substr(0, end);
    buffer_.erase(0, end + 4);
    if (head.rfind("HTTP/1.1 101", 0) != 0) throw std::runtime_error("WebSocket upgrade refused: " + head);
  }
  ~WebSocketClient() { ::close(fd_); }
  WebSocketClient(const WebSocketClient&) = delete;
  WebSocketClient& operator=(const WebSocketClient&) = delete;

  // The next complete message (fragments joined), or nothing by the timeout.
  std::optional<std::string> next(std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    std::string message;
    try {
      for (;;) {
        need(2, deadline);
        const bool fin = (buffer_[0] & 0x80) != 0;
        const int opcode = buffer_[0] & 0x0f;
        uint64_t length = static_cast<uint8_t>(buffer_[1]) & 0x7f;
        std::size_t header = 2;
        if (length == 126) {
          need(4, deadline);
          length = (uint64_t{static_cast<uint8_t>(buffer_[2])} << 8) | static_cast<uint8_t>(buffer_[3]);
          header = 4;
        } else if (length == 127) {
          need(10, deadline);
          length = 0;
          for (int i = 2; i < 10; ++i) length = (length << 8) | static_cast<uint8_t>(buffer_[i]);
          header = 10;
        }
        need(header + length, deadline);
        const std::string payload = buffer_.substr(header, length);
        buffer_.erase(0, header + length);
        if (opcode == 0x8) throw std::runtime_error("the server closed the WebSocket");
        if (opcode == 0x9 || opcode == 0xA) continue;  // ping / pong: nothing for the test
        message += payload;
        if (fin) return message;
      }
    } catch (const TimedOut&) {
      return std::nullopt;
    }
  }

  // A plain GET; returns the status line and body ("" on failure).
  static std::string http_get(uint16_t port, const std::string& path) {
    const int fd = connect_to(port);
    const std::string request = "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
    ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
    std::string reply;
    char chunk[65536];
    pollfd p{fd, POLLIN, 0};
    while (::poll(&p, 1, 10000) > 0) {
      const ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
      if (n <= 0) break;
      reply.append(chunk, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return reply;
  }

 private:
  struct TimedOut {};

  static int connect_to(uint16_t port) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    if (fd < 0) throw std::runtime_error("socket failed");
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
      ::close(fd);
      throw std::runtime_error("cannot connect to 127.0.0.1:" + std::to_string(port));
    }
    return fd;
  }

  void send_all(const std::string& data) {
    std::size_t sent = 0;
    while (sent < data.size()) {
      const ssize_t n = ::send(fd_, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
      if (n <= 0) throw std::runtime_error("send failed");
      sent += static_cast<std::size_t>(n);
    }
  }

  void need(std::size_t bytes, Clock::time_point deadline) {
    while (buffer_.size() < bytes) fill(deadline);
  }

  void fill(Clock::time_point deadline) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) throw TimedOut{};
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(left)) <= 0) throw TimedOut{};
    char chunk[65536];
    const ssize_t n = ::recv(fd_, chunk, sizeof chunk, 0);
    if (n <= 0) throw std::runtime_error("the viewer closed the connection");
    buffer_.append(chunk, static_cast<std::size_t>(n));
  }

  int fd_;
  std::string buffer_;
};

}  // namespace autonomy::test
