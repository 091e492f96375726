#include "live_bridge.hpp"

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <fstream>

#include <spdlog/spdlog.h>

#include "io/foxglove_ws/ws_endpoint.hpp"
#include "io/recording/record_file.hpp"
#include "framework/topic_types.hpp"
#include "topic_channels.hpp"
#include "viewer_source.hpp"

namespace gdnav::live {

LiveBridge::~LiveBridge() {
    if (server_) server_->stop();
}

void LiveBridge::configure(const config::Config& cfg, const framework::RunInfo& run, rnd::Stream&) {
    std::vector<std::string> topics = cfg.has("topics") ? cfg.get_strings("topics") : framework::known_topics();
    const bool with_viewer = cfg.get_bool("viewer", false);
    const auto viewer_decimation = static_cast<std::uint64_t>(cfg.get_int("viewer_decimation", 10, 1, 1000000));
    if (topics.empty() && !with_viewer)
        cfg.fail("topics", "at least one topic is required (or viewer: true; leave the key out: every data topic)");
    for (auto& t : topics) {
        const std::string full = io::recording::resolve_topic(t);
        if (full.empty())
            cfg.fail("topics", "unknown topic '" + t + "' (known: " + io::recording::known_topics_list() + ")");
        t = full;
    }
    // What a viewer shows as the server's name: gdnav and the run it belongs to.
    options_.name = "gdnav run " + std::to_string(run.run_index) + ", seed " + std::to_string(run.seed) +
                    (run.out_dir.empty() ? std::string() : " (" + run.out_dir + ")");
    options_.port = static_cast<std::uint16_t>(cfg.get_int("port", 8765, 1, 65535));
    options_.address = cfg.get_string("bind", "127.0.0.1");
    decimation_ = static_cast<std::uint64_t>(cfg.get_int("decimation", 10, 1, 1000000));
    options_.max_pending_bytes = static_cast<std::size_t>(cfg.get_int("max_pending_kib", 1024, 16, 1 << 20)) * 1024;
    options_.queue_frames = static_cast<std::size_t>(cfg.get_int("queue_steps", 64, 1, 65536));
    try {
        io::foxglove_ws::check_address(options_.address);
    } catch (const std::invalid_argument& e) {
        cfg.fail("bind", e.what());
    }
    try {  // here, so that a port in use is a configuration error before the run starts
        io::foxglove_ws::check_listen(options_.address, options_.port);
    } catch (const std::runtime_error& e) {
        cfg.fail("port", e.what());
    }
    if (!topics.empty()) sources_.push_back(std::make_unique<TopicChannels>(*this, topics, decimation_));
    if (with_viewer) sources_.push_back(std::make_unique<ViewerSource>(*this, viewer_decimation));  // after our inputs
    // Each input is read only at the steps some source streams (a shared input: both sources' steps), so over DDS
    // the producers send only those (InputBase::stride).
    const auto& viewer_topics = io::viewer::viewer_input_topics();
    for (framework::InputBase* in : inputs()) {
        std::uint64_t n = 0;
        if (std::find(topics.begin(), topics.end(), in->topic()) != topics.end()) n = std::gcd(n, decimation_);
        if (with_viewer && std::find(viewer_topics.begin(), viewer_topics.end(), in->topic()) != viewer_topics.end())
            n = std::gcd(n, viewer_decimation);
        in->set_stride(n);
    }
    run_ = run;
    step_ns_ = io::recording::step_ns(run.dt_s);
}

void LiveBridge::start_server() {
    std::vector<io::foxglove_ws::Channel> channels;
    first_ids_.clear();
    for (const auto& s : sources_) {
        first_ids_.push_back(static_cast<std::uint32_t>(channels.size() + 1));
        for (auto& c : s->channels()) channels.push_back(std::move(c));
    }
    const std::size_t n = channels.size();
    server_ = std::make_unique<io::foxglove_ws::Server>(options_, std::move(channels));
    server_->start();
    const bool v6 = options_.address.find(':') != std::string::npos;
    const std::string host = v6 ? "[" + options_.address + "]" : options_.address;
    spdlog::info("{}: Foxglove WebSocket server on ws://{}:{} ({} channels; topics every {} step(s))", name(), host,
                 options_.port, n, decimation_);
}

void LiveBridge::step(const framework::StepContext& ctx) {
    if (!server_) start_server();
    io::foxglove_ws::Frame frame;  // empty vectors: no allocation unless a source adds a message
    frame.log_time_ns = ctx.k * step_ns_;
    for (std::size_t i = 0; i < sources_.size(); ++i)
        sources_[i]->encode(ctx, frame.log_time_ns, first_ids_[i], *server_, frame);
    if (!frame.empty()) {
        if (server_->publish(std::move(frame))) ++steps_streamed_;
    } else if (ctx.k % decimation_ == 0 && server_->stalled_clients() > 0 && !server_->any_subscribed()) {
        server_->skip();  // every subscribed client is stalled: nothing serialised, counted as dropped for them
        ++steps_skipped_;
    }
}

void LiveBridge::finish(bool) {
    if (finished_) return;
    finished_ = true;
    io::foxglove_ws::ServerStats s;
    if (server_) {
        server_->stop();
        s = server_->stats();
    }
    spdlog::info("{}: {} steps streamed, {} not serialised (every subscribed client stalled), {} dropped at the "
                 "bridge (server thread behind), {} client(s)",
                 name(), steps_streamed_, steps_skipped_, s.frames_dropped_queue, s.clients.size());
    for (const auto& c : s.clients)
        spdlog::info("{}: client {} ({}): {} frames sent, {} frames dropped ({} messages sent, {} dropped), {} bytes",
                     name(), c.id, c.remote, c.frames_sent, c.frames_dropped, c.messages_sent, c.messages_dropped,
                     c.bytes_sent);
    if (run_.out_dir.empty()) return;
    const std::filesystem::path f = std::filesystem::path(run_.out_dir) / (name() + "_stats.yaml");
    std::ofstream o(f);
    o << "# live view statistics (components/live/live_bridge.hpp)\naddress: \"" << options_.address
      << "\"\nport: " << options_.port << "\ndecimation: " << decimation_ << "\nsteps_streamed: " << steps_streamed_
      << "\nsteps_skipped: " << steps_skipped_
      << "\nframes_dropped_queue: " << s.frames_dropped_queue << "\nclients:\n";
    for (const auto& c : s.clients)
        o << "  - {id: " << c.id << ", remote: \"" << c.remote << "\", frames_sent: " << c.frames_sent
          << ", frames_dropped: " << c.frames_dropped << ", messages_sent: " << c.messages_sent
          << ", messages_dropped: " << c.messages_dropped << ", bytes_sent: " << c.bytes_sent
          << ", subscriptions: " << c.subscriptions << "}\n";
    if (s.clients.empty()) o << "  []\n";
    if (!o) spdlog::warn("{}: cannot write {}", name(), f.string());
}

void register_live(framework::ComponentRegistry& reg) {
    reg.add("live", "streams topics to Foxglove over the Foxglove WebSocket protocol (gdnav run --live; docs/viewing.md)",
            framework::make_factory<LiveBridge>());
}

}  // namespace gdnav::live
