#include "io/foxglove_ws/server.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "io/foxglove_ws/ws_endpoint.hpp"

namespace gdnav::io::foxglove_ws {

void Frame::add(std::uint32_t channel_id, const std::uint8_t* data, std::size_t size) {
    messages.push_back({channel_id, bytes.size(), size});
    bytes.insert(bytes.end(), data, data + size);
}

Server::Server(ServerOptions options, std::vector<Channel> channels)
    : options_(std::move(options)), channels_(std::move(channels)),
      subscribers_(std::make_unique<std::atomic<std::uint32_t>[]>(channels_.size())) {
    for (std::size_t i = 0; i < channels_.size(); ++i) subscribers_[i].store(0);
    WsEndpoint::Handlers h;
    h.on_open = [this](std::uint64_t id, const std::string& remote) { on_open(id, remote); };
    h.on_close = [this](std::uint64_t id) { on_close(id); };
    h.on_text = [this](std::uint64_t id, const std::string& text) { on_text(id, text); };
    endpoint_ = std::make_unique<WsEndpoint>(kSubprotocol, std::move(h));
    endpoint_->set_ticker(options_.flush_period_s, [this] { drain(); });
}

Server::~Server() { stop(); }

void Server::start() {
    endpoint_->start(options_.address, options_.port);
    running_ = true;
}

bool Server::subscribed(std::uint32_t id) const noexcept {
    return id >= 1 && id <= channels_.size() && subscribers_[id - 1].load(std::memory_order_relaxed) > 0;
}

bool Server::publish(Frame frame) {
    if (!running_) return false;
    std::size_t waiting = 0;
    {
        std::lock_guard lock(queue_mutex_);
        if (queue_.size() >= options_.queue_frames) {
            frames_dropped_queue_.fetch_add(1, std::memory_order_relaxed);
            return false;
        }
        queue_.push_back(std::move(frame));
        waiting = queue_.size();
    }
    frames_published_.fetch_add(1, std::memory_order_relaxed);
    if (waiting >= options_.wake_frames && !drain_posted_.exchange(true)) endpoint_->post([this] { drain(); });
    return true;
}

void Server::drain() {
    drain_posted_.store(false);  // a frame published from now on posts again
    std::deque<Frame> frames;
    {
        std::lock_guard lock(queue_mutex_);
        frames.swap(queue_);
    }
    for (auto& [conn, c] : clients_)  // a stalled client whose backlog went down to half the limit is back
        if (c.stalled && endpoint_->buffered(conn) <= options_.max_pending_bytes / 2) set_stalled(c, false);
    for (const Frame& f : frames)
        for (auto& [conn, c] : clients_) send(conn, c, f);
}

void Server::send(std::uint64_t conn, Client& c, const Frame& f) {
    std::uint64_t wanted = 0;
    for (const auto& m : f.messages)
        if (c.subscription_of[m.channel_id - 1]) ++wanted;
    if (wanted == 0) return;
    if (!c.stalled && endpoint_->buffered(conn) > options_.max_pending_bytes) set_stalled(c, true);
    if (c.stalled) {
        ++c.stats.frames_dropped;
        c.stats.messages_dropped += wanted;
        return;
    }
    const std::vector<std::uint8_t> t = time_message(f.log_time_ns);
    endpoint_->send_binary(conn, t.data(), t.size());
    c.stats.bytes_sent += t.size();
    for (const auto& m : f.messages) {
        const auto& sub = c.subscription_of[m.channel_id - 1];
        if (!sub) continue;
        scratch_.resize(kMessageDataHeader + m.size);
        message_data_header(scratch_.data(), *sub, f.log_time_ns);
        std::memcpy(scratch_.data() + kMessageDataHeader, f.bytes.data() + m.offset, m.size);
        endpoint_->send_binary(conn, scratch_.data(), scratch_.size());
        ++c.stats.messages_sent;
        c.stats.bytes_sent += scratch_.size();
    }
    ++c.stats.frames_sent;
}

void Server::count_subscription(std::uint32_t channel_id, int delta) {
    if (delta > 0) {
        subscribers_[channel_id - 1].fetch_add(1, std::memory_order_relaxed);
        total_subscriptions_.fetch_add(1, std::memory_order_relaxed);
    } else {
        subscribers_[channel_id - 1].fetch_sub(1, std::memory_order_relaxed);
        total_subscriptions_.fetch_sub(1, std::memory_order_relaxed);
    }
}

void Server::set_stalled(Client& c, bool stalled) {
    if (c.stalled == stalled) return;
    c.stalled = stalled;
    for (const auto& [sub, ch] : c.channel_of) count_subscription(ch, stalled ? -1 : +1);
    if (stalled) {
        c.skipped_at_stall = frames_skipped_.load();
        stalled_clients_.fetch_add(1, std::memory_order_relaxed);
    } else {
        c.stats.frames_dropped += frames_skipped_.load() - c.skipped_at_stall;
        stalled_clients_.fetch_sub(1, std::memory_order_relaxed);
    }
}

void Server::on_open(std::uint64_t conn, const std::string& remote) {
    Client& c = clients_[conn];
    c.stats.id = conn;
    c.stats.remote = remote;
    c.subscription_of.assign(channels_.size(), std::nullopt);
    const auto session = std::chrono::duration_cast<std::chrono::nanoseconds>(
                             std::chrono::system_clock::now().time_since_epoch()).count();
    endpoint_->send_text(conn, server_info_json(options_.name, std::to_string(session)));
    endpoint_->send_text(conn, advertise_json(channels_, 1));
    spdlog::info("{}: client {} ({}) connected", options_.name, conn, remote);
}

void Server::on_close(std::uint64_t conn) {
    auto it = clients_.find(conn);
    if (it == clients_.end()) return;
    Client& c = it->second;
    set_stalled(c, false);  // the frames skipped while it was stalled count
    for (const auto& [sub, ch] : c.channel_of) count_subscription(ch, -1);
    c.stats.subscriptions = c.channel_of.size();
    spdlog::info("{}: client {} ({}) disconnected: {} frames sent, {} dropped", options_.name, conn, c.stats.remote,
                 c.stats.frames_sent, c.stats.frames_dropped);
    finished_.push_back(c.stats);
    clients_.erase(it);
}

void Server::on_text(std::uint64_t conn, const std::string& text) {
    auto it = clients_.find(conn);
    if (it == clients_.end()) return;
    Client& c = it->second;
    set_stalled(c, false);  // its subscriptions change: counted in again (a stalled client has some; send() decides)
    const ClientRequest r = parse_client_request(text);
    auto error = [&](const std::string& what) { endpoint_->send_text(conn, status_json(StatusLevel::Error, what)); };
    switch (r.kind) {
        case ClientRequest::Kind::Subscribe:
            for (const auto& [sub, ch] : r.subscriptions) {
                if (ch < 1 || ch > channels_.size()) {
                    error("subscribe: unknown channel " + std::to_string(ch));
                } else if (c.channel_of.count(sub)) {
                    error("subscribe: subscription id " + std::to_string(sub) + " is in use");
                } else if (c.subscription_of[ch - 1]) {
                    error("subscribe: channel " + std::to_string(ch) + " is already subscribed (subscription " +
                          std::to_string(*c.subscription_of[ch - 1]) + ")");
                } else {
                    c.channel_of[sub] = ch;
                    c.subscription_of[ch - 1] = sub;
                    count_subscription(ch, +1);
                }
            }
            break;
        case ClientRequest::Kind::Unsubscribe:
            for (const std::uint32_t sub : r.unsubscriptions) {
                auto s = c.channel_of.find(sub);
                if (s == c.channel_of.end()) {
                    error("unsubscribe: unknown subscription id " + std::to_string(sub));
                    continue;
                }
                c.subscription_of[s->second - 1].reset();
                count_subscription(s->second, -1);
                c.channel_of.erase(s);
            }
            break;
        case ClientRequest::Kind::Unsupported:
            error("unsupported operation '" + r.op + "' (this server streams data: subscribe, unsubscribe)");
            break;
        case ClientRequest::Kind::Invalid:
            error("invalid message: " + r.problem);
            break;
    }
}

void Server::stop() {
    if (!running_) return;
    running_ = false;
    endpoint_->post([this] { drain(); });  // the frames still queued go out before the connections close
    endpoint_->stop();  // joins the server thread: clients_ is ours from now on
    for (auto& [conn, c] : clients_) {
        set_stalled(c, false);
        c.stats.subscriptions = c.channel_of.size();
        finished_.push_back(c.stats);
    }
    clients_.clear();
    std::sort(finished_.begin(), finished_.end(), [](const ClientStats& a, const ClientStats& b) { return a.id < b.id; });
}

ServerStats Server::stats() const {
    if (running_) throw std::logic_error("foxglove_ws::Server::stats: call stop() first");
    ServerStats s;
    s.frames_published = frames_published_.load();
    s.frames_dropped_queue = frames_dropped_queue_.load();
    s.frames_skipped = frames_skipped_.load();
    s.clients = finished_;
    return s;
}

}  // namespace gdnav::io::foxglove_ws
