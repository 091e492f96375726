#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/foxglove_ws/protocol.hpp"
#include "io/foxglove_ws/server.hpp"

using namespace gdnav::io::foxglove_ws;
using nlohmann::json;

namespace {

std::uint64_t le(const std::uint8_t* p, int n) {
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = (v << 8) | p[i];
    return v;
}

int free_port() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof(a));
    socklen_t n = sizeof(a);
    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &n);
    close(fd);
    return ntohs(a.sin_port);
}

// A minimal WebSocket client on a blocking socket (RFC 6455: masked frames out, unmasked frames in).
class RawClient {
public:
    RawClient(int port, int rcvbuf = 0) {
        fd_ = socket(AF_INET, SOCK_STREAM, 0);
        if (rcvbuf > 0) setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof(rcvbuf));
        timeval tv{5, 0};
        setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof(tv));
        sockaddr_in a{};
        a.sin_family = AF_INET;
        a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        a.sin_port = htons(static_cast<std::uint16_t>(port));
        ok_ = connect(fd_, reinterpret_cast<sockaddr*>(&a), sizeof(a)) == 0;
    }
    ~RawClient() { close(fd_); }
    bool handshake(const std::string& subprotocol, std::string& response) {
        const std::string req = "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
                                "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
                                "Sec-WebSocket-Protocol: " + subprotocol + "\r\n\r\n";
        if (!ok_ || ::send(fd_, req.data(), req.size(), 0) != static_cast<ssize_t>(req.size())) return false;
        while (response.find("\r\n\r\n") == std::string::npos) {
            char c;
            if (recv(fd_, &c, 1, 0) != 1) return false;
            response += c;
        }
        return response.rfind("HTTP/1.1 101", 0) == 0;
    }
    void send_text(const std::string& s) {
        std::vector<std::uint8_t> f{0x81};
        if (s.size() < 126) {
            f.push_back(static_cast<std::uint8_t>(0x80 | s.size()));
        } else {
            f.push_back(0x80 | 126);
            f.push_back(static_cast<std::uint8_t>(s.size() >> 8));
            f.push_back(static_cast<std::uint8_t>(s.size()));
        }
        f.insert(f.end(), {0, 0, 0, 0});  // mask key 0: the payload is sent as is
        f.insert(f.end(), s.begin(), s.end());
        ::send(fd_, f.data(), f.size(), 0);
    }
    // One frame: opcode and payload (false on timeout or close).
    bool read_frame(int& opcode, std::vector<std::uint8_t>& payload) {
        std::uint8_t h[2];
        if (!read_all(h, 2)) return false;
        opcode = h[0] & 0x0f;
        std::uint64_t n = h[1] & 0x7f;
        if (n == 126 || n == 127) {
            std::uint8_t e[8];
            const int k = n == 126 ? 2 : 8;
            if (!read_all(e, k)) return false;
            n = 0;
            for (int i = 0; i < k; ++i) n = (n << 8) | e[i];
        }
        payload.resize(n);
        return n == 0 || read_all(payload.data(), n);
    }
    json read_json() {
        int op = 0;
        std::vector<std::uint8_t> p;
        if (!read_frame(op, p) || op != 1) return json();
        return json::parse(std::string(p.begin(), p.end()));
    }

private:
    bool read_all(std::uint8_t* p, std::size_t n) {
        while (n > 0) {
            const ssize_t r = recv(fd_, p, n, 0);
            if (r <= 0) return false;
            p += r;
            n -= static_cast<std::size_t>(r);
        }
        return true;
    }
    int fd_{-1};
    bool ok_{false};
};

std::vector<Channel> two_channels() {
    return {{"a/one", "cdr", "m::One", "omgidl", "module m { struct One { double x; }; };"},
            {"a/two", "cdr", "m::Two", "omgidl", "module m { struct Two { long y; }; };"}};
}

bool wait_until(const std::function<bool()>& f) {
    for (int i = 0; i < 500 && !f(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    return f();
}

}  // namespace

TEST(FoxgloveWsProtocol, MessagesFollowTheSpec) {
    std::uint8_t h[kMessageDataHeader];
    message_data_header(h, 0x01020304u, 0x1122334455667788ull);
    EXPECT_EQ(h[0], 0x01);
    EXPECT_EQ(le(h + 1, 4), 0x01020304u);
    EXPECT_EQ(le(h + 5, 8), 0x1122334455667788ull);
    const auto t = time_message(42);
    ASSERT_EQ(t.size(), 9u);
    EXPECT_EQ(t[0], 0x02);
    EXPECT_EQ(le(t.data() + 1, 8), 42u);

    const json adv = json::parse(advertise_json(two_channels(), 1));
    EXPECT_EQ(adv["op"], "advertise");
    ASSERT_EQ(adv["channels"].size(), 2u);
    EXPECT_EQ(adv["channels"][1]["id"], 2);
    EXPECT_EQ(adv["channels"][1]["topic"], "a/two");
    EXPECT_EQ(adv["channels"][1]["encoding"], "cdr");
    EXPECT_EQ(adv["channels"][1]["schemaName"], "m::Two");
    EXPECT_EQ(adv["channels"][1]["schemaEncoding"], "omgidl");
    const json info = json::parse(server_info_json("x", "7"));
    EXPECT_EQ(info["op"], "serverInfo");
    EXPECT_EQ(info["capabilities"], json::array({"time"}));

    const ClientRequest s = parse_client_request(R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":3}]})");
    ASSERT_EQ(s.kind, ClientRequest::Kind::Subscribe);
    ASSERT_EQ(s.subscriptions.size(), 1u);
    EXPECT_EQ(s.subscriptions[0], std::make_pair(0u, 3u));
    const ClientRequest u = parse_client_request(R"({"op":"unsubscribe","subscriptionIds":[4,5]})");
    ASSERT_EQ(u.kind, ClientRequest::Kind::Unsubscribe);
    EXPECT_EQ(u.unsubscriptions, (std::vector<std::uint32_t>{4, 5}));
    EXPECT_EQ(parse_client_request(R"({"op":"getParameters"})").kind, ClientRequest::Kind::Unsupported);
    EXPECT_EQ(parse_client_request("not json").kind, ClientRequest::Kind::Invalid);
    EXPECT_EQ(parse_client_request(R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":3}]})").kind,
              ClientRequest::Kind::Invalid);
}

TEST(FoxgloveWsServer, AdvertisesSubscribesAndSendsOnlySubscribedChannels) {
    ServerOptions o;
    o.port = static_cast<std::uint16_t>(free_port());
    Server server(o, two_channels());
    server.start();
    {
        RawClient refused(o.port);
        std::string response;
        EXPECT_FALSE(refused.handshake("another.protocol", response)) << response;
    }
    RawClient c(o.port);
    std::string response;
    ASSERT_TRUE(c.handshake(kSubprotocol, response)) << response;
    EXPECT_NE(response.find("Sec-WebSocket-Protocol: foxglove.websocket.v1"), std::string::npos) << response;
    EXPECT_EQ(c.read_json()["op"], "serverInfo");
    const json adv = c.read_json();
    ASSERT_EQ(adv["op"], "advertise");
    EXPECT_EQ(adv["channels"].size(), 2u);
    EXPECT_FALSE(server.any_subscribed());

    c.send_text(R"({"op":"subscribe","subscriptions":[{"id":7,"channelId":2}]})");
    ASSERT_TRUE(wait_until([&] { return server.subscribed(2); }));
    EXPECT_FALSE(server.subscribed(1));
    Frame f;
    f.log_time_ns = 123456789;
    const std::uint8_t one[] = {1, 2, 3}, two[] = {9, 8};
    f.add(1, one, sizeof(one));
    f.add(2, two, sizeof(two));
    ASSERT_TRUE(server.publish(std::move(f)));
    int op = 0;
    std::vector<std::uint8_t> p;
    ASSERT_TRUE(c.read_frame(op, p));
    EXPECT_EQ(op, 2);  // binary: Time
    ASSERT_EQ(p.size(), 9u);
    EXPECT_EQ(p[0], kOpTime);
    EXPECT_EQ(le(p.data() + 1, 8), 123456789u);
    ASSERT_TRUE(c.read_frame(op, p));
    EXPECT_EQ(op, 2);  // binary: Message Data of channel 2 only
    ASSERT_EQ(p.size(), kMessageDataHeader + 2);
    EXPECT_EQ(p[0], kOpMessageData);
    EXPECT_EQ(le(p.data() + 1, 4), 7u);
    EXPECT_EQ(le(p.data() + 5, 8), 123456789u);
    EXPECT_EQ(p[13], 9);
    EXPECT_EQ(p[14], 8);

    c.send_text(R"({"op":"subscribe","subscriptions":[{"id":8,"channelId":5}]})");
    const json st = c.read_json();
    EXPECT_EQ(st["op"], "status");
    EXPECT_EQ(st["level"], 2);
    c.send_text(R"({"op":"unsubscribe","subscriptionIds":[7]})");
    ASSERT_TRUE(wait_until([&] { return !server.any_subscribed(); }));

    server.stop();
    const ServerStats s = server.stats();
    EXPECT_EQ(s.frames_published, 1u);
    ASSERT_EQ(s.clients.size(), 1u);  // the refused handshake is no client
    EXPECT_EQ(s.clients[0].frames_sent, 1u);
    EXPECT_EQ(s.clients[0].messages_sent, 1u);
    EXPECT_EQ(s.clients[0].frames_dropped, 0u);
}

TEST(FoxgloveWsServer, ClientThatStopsReadingLosesFramesNeverThePublisher) {
    ServerOptions o;
    o.port = static_cast<std::uint16_t>(free_port());
    o.max_pending_bytes = 16 * 1024;
    Server server(o, two_channels());
    server.start();
    RawClient c(o.port, 4096);  // a small receive buffer; it reads nothing after subscribing
    std::string response;
    ASSERT_TRUE(c.handshake(kSubprotocol, response));
    c.send_text(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
    ASSERT_TRUE(wait_until([&] { return server.subscribed(1); }));
    const std::vector<std::uint8_t> payload(10000, 0x5a);
    std::uint64_t accepted = 0;
    for (int k = 0; k < 3000; ++k) {
        Frame f;
        f.log_time_ns = static_cast<std::uint64_t>(k);
        f.add(1, payload.data(), payload.size());
        if (server.publish(std::move(f))) ++accepted;
        if (k % 16 == 0) std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    server.stop();
    const ServerStats s = server.stats();
    ASSERT_EQ(s.clients.size(), 1u);
    const ClientStats& cs = s.clients[0];
    EXPECT_EQ(s.frames_published, accepted);
    EXPECT_EQ(s.frames_published + s.frames_dropped_queue, 3000u);
    EXPECT_GT(cs.frames_sent, 0u);
    EXPECT_GT(cs.frames_dropped, 0u);
    // Every accepted frame was either sent to the client or dropped for it (and counted): nothing waits unbounded.
    EXPECT_EQ(cs.frames_sent + cs.frames_dropped, accepted);
    EXPECT_EQ(cs.messages_dropped, cs.frames_dropped);
    EXPECT_EQ(s.frames_skipped, 0u);
    // What was handed to the connection is bounded by the socket buffers plus max_pending_bytes plus one frame.
    EXPECT_LT(cs.frames_sent * (payload.size() + kMessageDataHeader), 30000u * 1000u);
}

TEST(FoxgloveWsServer, StalledOnlyClientsStopTheProducerAndCountItsSkippedFrames) {
    ServerOptions o;
    o.port = static_cast<std::uint16_t>(free_port());
    o.max_pending_bytes = 16 * 1024;
    Server server(o, two_channels());
    server.start();
    RawClient c(o.port, 4096);
    std::string response;
    ASSERT_TRUE(c.handshake(kSubprotocol, response));
    c.send_text(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
    ASSERT_TRUE(wait_until([&] { return server.subscribed(1); }));
    const std::vector<std::uint8_t> payload(10000, 0x5a);
    std::uint64_t published = 0, skipped = 0;
    // As the live bridge does: serialise only for a subscriber that is not stalled; otherwise skip().
    for (int k = 0; k < 3000; ++k) {
        if (server.subscribed(1)) {
            Frame f;
            f.add(1, payload.data(), payload.size());
            if (server.publish(std::move(f))) ++published;
        } else if (server.stalled_clients() > 0) {
            server.skip();
            ++skipped;
        }
        if (k % 16 == 0) std::this_thread::sleep_for(std::chrono::microseconds(500));
    }
    EXPECT_GT(skipped, 0u);  // the client stalled: the producer stopped making frames
    // Not asserted: that it is still stalled now. The kernel may take more of its backlog later (loopback TCP
    // buffers grow), which brings it back below half the limit; seen once on a loaded machine.
    EXPECT_LE(server.stalled_clients(), 1u);
    server.stop();
    const ServerStats s = server.stats();
    ASSERT_EQ(s.clients.size(), 1u);
    EXPECT_EQ(s.frames_skipped, skipped);
    EXPECT_EQ(s.clients[0].frames_sent + s.clients[0].frames_dropped, published + skipped);
}
