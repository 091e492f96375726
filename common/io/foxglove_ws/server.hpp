#pragma once
// A Foxglove WebSocket server for a producer that must never wait (a lockstep simulation member):
//
//   Server s(options, channels);          // channels get ids 1..N (advertised to every client on connection)
//   s.start();                            // listens on options.address:options.port; one server thread
//   if (s.subscribed(id)) frame.add(id, bytes, n);   // each step: serialise only what some client wants
//   s.publish(std::move(frame));          // never blocks (below)
//   s.stop(); s.stats();                  // sent and dropped frames per client
//
// Drop policy (nothing is queued without bound):
//  * publish() puts the frame into a queue of at most `queue_frames` frames; when the queue is full the frame is
//    dropped at once (counted: frames_dropped_queue). The server thread takes the queued frames every
//    `flush_period_s` and whenever `wake_frames` are waiting (then publish() wakes it). The producer's cost is a
//    mutex held for a push, and one wake-up of the server thread per `wake_frames` frames at most.
//  * The server thread sends each frame to each client that subscribed to one of its channels (a Time message, then
//    one Message Data per subscribed channel), unless that client already has more than `max_pending_bytes` handed to
//    its connection and not yet accepted by its socket (a slow or stalled viewer): then the whole frame is dropped for
//    that client only and counted (ClientStats::frames_dropped, messages_dropped). Other clients are unaffected.
//  * Such a client is "stalled" until its backlog falls to half the limit (looked at every flush period): its
//    subscriptions do not count in subscribed() / any_subscribed(), so when every subscribed client is stalled the
//    producer serialises nothing and calls skip() instead (a counter); each stalled client counts the frames skipped
//    meanwhile in its frames_dropped (not in messages_dropped: they were never made).
#include <atomic>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "io/foxglove_ws/protocol.hpp"

namespace gdnav::io::foxglove_ws {

class WsEndpoint;

struct ServerOptions {
    std::string name{"gdnav"};          // serverInfo name
    std::string address{"127.0.0.1"};   // listen address (IPv4 or IPv6 literal, or "localhost")
    std::uint16_t port{8765};
    std::size_t max_pending_bytes{1u << 20};  // per client, see the drop policy
    std::size_t queue_frames{64};             // frames waiting for the server thread
    std::size_t wake_frames{16};              // publish() wakes the server thread when this many frames wait
    double flush_period_s{0.005};             // and the server thread looks at the queue this often
};

// The messages of one instant (one simulation step): channel id + payload, one log time.
struct Frame {
    struct Message {
        std::uint32_t channel_id;
        std::size_t offset, size;  // in bytes
    };
    std::uint64_t log_time_ns{0};
    std::vector<std::uint8_t> bytes;
    std::vector<Message> messages;
    void add(std::uint32_t channel_id, const std::uint8_t* data, std::size_t size);
    [[nodiscard]] bool empty() const { return messages.empty(); }
};

struct ClientStats {
    std::uint64_t id{0};  // 1, 2, ... in connection order
    std::string remote;
    std::uint64_t frames_sent{0}, frames_dropped{0};      // frames holding at least one subscribed channel
    std::uint64_t messages_sent{0}, messages_dropped{0};  // Message Data messages
    std::uint64_t bytes_sent{0};                          // handed to the connection (all messages)
    std::size_t subscriptions{0};                         // at the end
};

struct ServerStats {
    std::uint64_t frames_published{0};      // accepted by publish()
    std::uint64_t frames_dropped_queue{0};  // publish() found the queue full
    std::uint64_t frames_skipped{0};        // skip() calls
    std::vector<ClientStats> clients;       // every client that connected, in connection order
};

class Server {
public:
    Server(ServerOptions options, std::vector<Channel> channels);
    ~Server();
    Server(const Server&) = delete;
    Server& operator=(const Server&) = delete;

    // Listens and starts the server thread; throws std::runtime_error("cannot listen on ADDR:PORT: reason").
    void start();
    // Whether some client that is not stalled is subscribed to channel `id` / to any channel (atomics: any thread).
    [[nodiscard]] bool subscribed(std::uint32_t id) const noexcept;
    [[nodiscard]] bool any_subscribed() const noexcept { return total_subscriptions_.load(std::memory_order_relaxed) > 0; }
    // Subscribed clients that are stalled (any thread).
    [[nodiscard]] std::uint32_t stalled_clients() const noexcept { return stalled_clients_.load(std::memory_order_relaxed); }
    // Hands a frame to the server thread; never blocks; false when dropped (queue full or not running).
    bool publish(Frame frame);
    // A frame the producer did not make because every subscribed client is stalled (counted as dropped for them).
    void skip() noexcept { frames_skipped_.fetch_add(1, std::memory_order_relaxed); }
    // Closes the clients and stops the server thread (frames still queued are not sent). Idempotent.
    void stop();
    // The final figures (after stop()).
    [[nodiscard]] ServerStats stats() const;
    [[nodiscard]] const std::vector<Channel>& channels() const { return channels_; }

private:
    struct Client {
        ClientStats stats;
        std::map<std::uint32_t, std::uint32_t> channel_of;          // subscription id -> channel id
        std::vector<std::optional<std::uint32_t>> subscription_of;  // channel id - 1 -> subscription id
        bool stalled{false};
        std::uint64_t skipped_at_stall{0};  // frames_skipped_ when it stalled
    };
    // Server thread.
    void on_open(std::uint64_t conn, const std::string& remote);
    void on_close(std::uint64_t conn);
    void on_text(std::uint64_t conn, const std::string& text);
    void drain();
    void send(std::uint64_t conn, Client& c, const Frame& f);
    void count_subscription(std::uint32_t channel_id, int delta);
    void set_stalled(Client& c, bool stalled);  // counts its subscriptions out / back in

    ServerOptions options_;
    std::vector<Channel> channels_;
    std::unique_ptr<std::atomic<std::uint32_t>[]> subscribers_;  // per channel
    std::atomic<std::uint32_t> total_subscriptions_{0};
    std::unique_ptr<WsEndpoint> endpoint_;
    bool running_{false};

    std::mutex queue_mutex_;
    std::deque<Frame> queue_;
    std::atomic<bool> drain_posted_{false};
    std::atomic<std::uint64_t> frames_published_{0}, frames_dropped_queue_{0}, frames_skipped_{0};
    std::atomic<std::uint32_t> stalled_clients_{0};

    std::map<std::uint64_t, Client> clients_;  // server thread (and the caller once stopped)
    std::vector<ClientStats> finished_;        // clients gone
    std::vector<std::uint8_t> scratch_;        // one outgoing binary message
};

}  // namespace gdnav::io::foxglove_ws
