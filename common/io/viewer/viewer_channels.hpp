#pragma once
// Viewer-ready channels: derived messages in public Foxglove schemas (and one small gdnav schema) that Foxglove and
// Lichtblick draw without set-up (docs/viewing.md "Viewer channels"). Used by the recorder (`--record ...,viewer`:
// extra MCAP channels) and meant for any other owner (a live bridge) — nothing here knows about files or sockets.
//
//   topic                schema (omgidl, message encoding cdr)  content
//   /viewer/true/fix     foxglove::LocationFix                  Truth lat/lon [deg], h [m]           (Map panel)
//   /viewer/est/fix      foxglove::LocationFix                  PositionEstimate lat/lon/h           (Map panel)
//   /viewer/true/tf      foxglove::FrameTransform               enu -> body_true: Truth position and attitude
//   /viewer/est/tf       foxglove::FrameTransform               enu -> body_est: estimated position and attitude
//   /viewer/nav_errors   gdnav::viewer::NavErrors               attitude/horizontal/altitude/speed errors, gnss_denied
//   /viewer/true/pose    foxglove::PoseInFrame                  in `enu`: Truth position and attitude (the tf's pose)
//   /viewer/est/pose     foxglove::PoseInFrame                  in `enu`: estimated position and attitude
//
// Frames (3D panel, z up): `enu` = East-North-Up tangent plane at the first true position the owner saw (its origin),
// body frames x forward, y left, z up (viewer_math.hpp). Timestamps (foxglove::Time) = the log time the owner gives
// (the recording's: k * step_ns since step 0). Errors = common/core/metrics (run.h5 /error), in degrees where angular.
// Position covariance: not known to the viewer channels (type UNKNOWN, zeros).
//
// The owner calls encode() at every step; a message is produced at the steps k % decimation == 0 when its inputs are
// available (Truth for the true channels; Truth, AttitudeEstimate, PositionEstimate and AirDataEstimate for the
// estimated ones and the errors). The inputs are the owner's existing Lag::Same inputs of those topics, or new ones
// declared on the owner (so the owner's run needs producers of the four topics).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "earth/wgs84.hpp"
#include "framework/component.hpp"

namespace gdnav::io::viewer {

struct ViewerChannel {
    std::string topic;
    std::string schema_name;
    std::string schema_encoding;  // "omgidl"
    std::string schema;           // the whole IDL text a viewer parses (no #include)
    std::string message_encoding;  // "cdr"
};

// The channels, in the order encode() indexes them.
const std::vector<ViewerChannel>& viewer_channels();
// True for a channel of viewer_channels() (same topic, schema name and encodings): a reader of gdnav recordings skips
// these derived channels instead of refusing them as foreign.
bool is_viewer_channel(const std::string& topic, const std::string& schema_name, const std::string& schema_encoding,
                       const std::string& message_encoding);

struct ViewerOptions {
    std::uint64_t decimation{10};  // steps per viewer message (10: 10 Hz at dt = 0.01 s)
};

// The topics the channels are derived from (Truth and the three estimates): a run writing all four can show them.
const std::vector<std::string>& viewer_input_topics();

// One encoded message: index into channels() and its CDR bytes (4-byte encapsulation header included).
using ViewerMessage = std::pair<std::size_t, std::vector<std::uint8_t>>;

class ViewerChannels {
public:
    // Finds or declares the inputs on `owner` (call it from the owner's configure(), after the owner's own inputs).
    ViewerChannels(framework::Component& owner, ViewerOptions options);
    ~ViewerChannels();
    ViewerChannels(const ViewerChannels&) = delete;
    ViewerChannels& operator=(const ViewerChannels&) = delete;

    [[nodiscard]] const std::vector<ViewerChannel>& channels() const { return viewer_channels(); }
    [[nodiscard]] std::uint64_t decimation() const { return options_.decimation; }
    // True once encode() has seen a true position (the ENU origin of the transforms and the errors' radii).
    [[nodiscard]] bool has_origin() const { return have_origin_; }
    // Appends this step's messages to `out` (nothing at steps between decimated ones). `log_time_ns`: the step's log
    // time, written as every message's foxglove::Time timestamp.
    void encode(const framework::StepContext& ctx, std::uint64_t log_time_ns, std::vector<ViewerMessage>& out);

private:
    const framework::InputBase& input(framework::Component& owner, const std::string& topic,
                                      const msg::MessageOps& ops);

    ViewerOptions options_;
    std::vector<std::unique_ptr<framework::InputBase>> owned_;  // inputs the owner did not have
    const framework::InputBase* truth_{nullptr};
    const framework::InputBase* att_{nullptr};
    const framework::InputBase* pos_{nullptr};
    const framework::InputBase* air_{nullptr};
    bool have_origin_{false};
    earth::Geodetic origin_;
    earth::Radii radii0_;
};

}  // namespace gdnav::io::viewer
