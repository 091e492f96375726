#pragma once
// The WebSocket transport of the Foxglove server (server.hpp): one listening socket and its connections, served by
// one thread (Debian's websocketpp over standalone asio). Connections must ask for the server's subprotocol (others
// are refused during the handshake). Handlers, sends and buffered() run on that thread only (post() gets there).
// No websocketpp type in this header: ws_endpoint.cpp alone includes websocketpp (compiled as C++17, see
// CMakeLists.txt).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace gdnav::io::foxglove_ws {

class WsEndpoint {
public:
    using ConnId = std::uint64_t;  // 1, 2, ... in the order connections open
    struct Handlers {
        std::function<void(ConnId, const std::string& remote)> on_open;
        std::function<void(ConnId)> on_close;  // closed or failed
        std::function<void(ConnId, const std::string& text)> on_text;
    };
    WsEndpoint(std::string subprotocol, Handlers handlers);
    ~WsEndpoint();  // stop()
    WsEndpoint(const WsEndpoint&) = delete;
    WsEndpoint& operator=(const WsEndpoint&) = delete;

    // Runs `f` on the server thread every `period_s` seconds from start() on (call before start()).
    void set_ticker(double period_s, std::function<void()> f);
    // Binds address:port and starts the thread. Throws std::runtime_error("cannot listen on ADDR:PORT: reason").
    void start(const std::string& address, std::uint16_t port);
    // Runs `f` on the server thread (does nothing once stopped). Any thread.
    void post(std::function<void()> f);
    // Server thread only. A send to a connection that is gone does nothing.
    void send_text(ConnId id, const std::string& text);
    void send_binary(ConnId id, const void* data, std::size_t size);
    // Bytes handed to the connection and not yet accepted by the socket (0 for a connection that is gone).
    [[nodiscard]] std::size_t buffered(ConnId id) const;
    // Stops listening, closes every connection (waits at most `grace_s` for the close handshakes, and not at all when
    // every connection has a backlog: a client that does not read is not waited for), stops and joins the thread.
    // Idempotent.
    void stop(double grace_s = 0.5);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Throws std::invalid_argument("'ADDR' is not an IPv4 or IPv6 address or localhost") for an address no socket can
// listen on.
void check_address(const std::string& address);
// Throws std::runtime_error("cannot listen on ADDR:PORT: reason") when a socket cannot be bound to address:port
// now (a port in use, an address of no interface); binds and closes at once. check_address() first.
void check_listen(const std::string& address, std::uint16_t port);

}  // namespace gdnav::io::foxglove_ws
