// websocketpp 0.8.2 is not valid C++20: this file is compiled as C++17 (CMakeLists.txt).
#include "io/foxglove_ws/ws_endpoint.hpp"

#include <atomic>
#include <chrono>
#include <future>
#include <map>
#include <stdexcept>
#include <thread>
#include <vector>

#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

namespace gdnav::io::foxglove_ws {

namespace {
using WsServer = websocketpp::server<websocketpp::config::asio>;
using Hdl = websocketpp::connection_hdl;

std::string where(const std::string& address, std::uint16_t port) {
    return address.find(':') != std::string::npos ? "[" + address + "]:" + std::to_string(port)
                                                  : address + ":" + std::to_string(port);
}

asio::ip::address address_of(const std::string& address) {
    asio::error_code ec;
    const asio::ip::address a = asio::ip::make_address(address == "localhost" ? "127.0.0.1" : address, ec);
    if (ec) throw std::invalid_argument("'" + address + "' is not an IPv4 or IPv6 address or localhost");
    return a;
}

asio::ip::tcp::endpoint endpoint_of(const std::string& address, std::uint16_t port) {
    try {
        return {address_of(address), port};
    } catch (const std::invalid_argument& e) {
        throw std::runtime_error("cannot listen on " + where(address, port) + ": " + e.what());
    }
}
}  // namespace

struct WsEndpoint::Impl {
    std::string subprotocol;
    Handlers handlers;
    asio::io_context io;  // declared before the server, which refers to it
    WsServer server;
    std::map<Hdl, ConnId, std::owner_less<Hdl>> ids;  // server thread only
    std::map<ConnId, Hdl> hdls;
    ConnId next{1};
    std::thread thread;
    std::unique_ptr<asio::steady_timer> timer;
    std::chrono::nanoseconds period{0};
    std::function<void()> tick;
    void arm() {
        timer->expires_after(period);
        timer->async_wait([this](const asio::error_code& ec) {
            if (ec || stopped) return;
            tick();
            arm();
        });
    }
    std::future<void> done;
    bool started{false};
    std::atomic<bool> stopped{false};

    WsServer::connection_ptr con(ConnId id) const {
        auto it = hdls.find(id);
        if (it == hdls.end()) return nullptr;
        websocketpp::lib::error_code ec;
        auto c = const_cast<WsServer&>(server).get_con_from_hdl(it->second, ec);
        return ec ? nullptr : c;
    }
    void closed(Hdl h) {
        auto it = ids.find(h);
        if (it == ids.end()) return;
        const ConnId id = it->second;
        ids.erase(it);
        hdls.erase(id);
        if (handlers.on_close) handlers.on_close(id);
    }
};

WsEndpoint::WsEndpoint(std::string subprotocol, Handlers handlers) : impl_(std::make_unique<Impl>()) {
    impl_->subprotocol = std::move(subprotocol);
    impl_->handlers = std::move(handlers);
    Impl* p = impl_.get();
    WsServer& s = p->server;
    s.clear_access_channels(websocketpp::log::alevel::all);
    s.clear_error_channels(websocketpp::log::elevel::all);
    s.init_asio(&p->io);
    s.set_reuse_addr(true);
    s.set_validate_handler([p](Hdl h) {
        auto c = p->server.get_con_from_hdl(h);
        for (const auto& sp : c->get_requested_subprotocols())
            if (sp == p->subprotocol) {
                c->select_subprotocol(sp);
                return true;
            }
        return false;  // the handshake is refused
    });
    s.set_open_handler([p](Hdl h) {
        const ConnId id = p->next++;
        p->ids[h] = id;
        p->hdls[id] = h;
        if (p->handlers.on_open) p->handlers.on_open(id, p->server.get_con_from_hdl(h)->get_remote_endpoint());
    });
    s.set_close_handler([p](Hdl h) { p->closed(h); });
    s.set_fail_handler([p](Hdl h) { p->closed(h); });
    s.set_message_handler([p](Hdl h, WsServer::message_ptr m) {
        auto it = p->ids.find(h);
        if (it == p->ids.end() || m->get_opcode() != websocketpp::frame::opcode::text) return;
        if (p->handlers.on_text) p->handlers.on_text(it->second, m->get_payload());
    });
}

WsEndpoint::~WsEndpoint() { stop(); }

void WsEndpoint::set_ticker(double period_s, std::function<void()> f) {
    if (impl_->started) throw std::logic_error("WsEndpoint::set_ticker: after start()");
    impl_->period = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::duration<double>(period_s));
    impl_->tick = std::move(f);
}

void WsEndpoint::start(const std::string& address, std::uint16_t port) {
    if (impl_->started) throw std::logic_error("WsEndpoint::start: started twice");
    websocketpp::lib::error_code ec;
    impl_->server.listen(endpoint_of(address, port), ec);
    if (!ec) impl_->server.start_accept(ec);
    if (ec) throw std::runtime_error("cannot listen on " + where(address, port) + ": " + ec.message());
    impl_->started = true;
    if (impl_->tick) {
        impl_->timer = std::make_unique<asio::steady_timer>(impl_->io);
        impl_->arm();
    }
    std::packaged_task<void()> task([this] { impl_->server.run(); });
    impl_->done = task.get_future();
    impl_->thread = std::thread(std::move(task));
}

void WsEndpoint::post(std::function<void()> f) {
    if (!impl_->started || impl_->stopped) return;
    asio::post(impl_->io, std::move(f));
}

void WsEndpoint::send_text(ConnId id, const std::string& text) {
    auto c = impl_->con(id);
    if (c) c->send(text, websocketpp::frame::opcode::text);
}

void WsEndpoint::send_binary(ConnId id, const void* data, std::size_t size) {
    auto c = impl_->con(id);
    if (c) c->send(data, size, websocketpp::frame::opcode::binary);
}

std::size_t WsEndpoint::buffered(ConnId id) const {
    auto c = impl_->con(id);
    return c ? c->get_buffered_amount() : 0;
}

void WsEndpoint::stop(double grace_s) {
    if (!impl_->started || impl_->stopped) return;
    impl_->stopped = true;
    Impl* p = impl_.get();
    auto closing = std::make_shared<std::promise<bool>>();  // true: some connection can finish its close handshake
    std::future<bool> waiting = closing->get_future();
    asio::post(p->io, [p, closing] {
        websocketpp::lib::error_code ec;
        if (p->timer) p->timer->cancel();
        p->server.stop_listening(ec);
        bool can_close = false;
        std::vector<Hdl> open;
        for (const auto& [id, h] : p->hdls) open.push_back(h);
        for (const auto& h : open) {
            auto c = p->server.get_con_from_hdl(h, ec);
            if (!ec && c->get_buffered_amount() == 0) can_close = true;  // a backlog: its close frame waits behind it
            p->server.close(h, websocketpp::close::status::going_away, "server stopping", ec);
        }
        closing->set_value(can_close);
    });
    // The thread returns by itself once every connection is closed. Connections with a backlog (a client that does
    // not read) are not waited for; the others get `grace_s` to answer the close.
    const bool wait = waiting.wait_for(std::chrono::seconds(2)) == std::future_status::ready && waiting.get();
    if (!wait || p->done.wait_for(std::chrono::duration<double>(grace_s)) != std::future_status::ready) p->io.stop();
    p->thread.join();
}

void check_address(const std::string& address) { (void)address_of(address); }

void check_listen(const std::string& address, std::uint16_t port) {
    asio::io_context io;
    asio::ip::tcp::acceptor a(io);
    const asio::ip::tcp::endpoint ep = endpoint_of(address, port);
    asio::error_code ec;
    a.open(ep.protocol(), ec);
    if (!ec) a.set_option(asio::socket_base::reuse_address(true), ec);
    if (!ec) a.bind(ep, ec);
    if (!ec) a.listen(asio::socket_base::max_listen_connections, ec);
    if (ec) throw std::runtime_error("cannot listen on " + where(address, port) + ": " + ec.message());
}

}  // namespace gdnav::io::foxglove_ws
