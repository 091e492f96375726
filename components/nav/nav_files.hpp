#pragma once
// What the three nav components share: the two navigation files they read (the tuning file and a variant file), the
// `init_mode` override, and the component bases around one filter. Each component is a file of its own (nav_air.cpp,
// nav_att.cpp, nav_pos.cpp); nav_components.cpp registers them.
#include <cstdint>
#include <optional>

#include "config/config.hpp"
#include "framework/registry.hpp"
#include "model/in_flight_aligner.hpp"
#include "model/nav_init.hpp"
#include "random/stream.hpp"
#include "rejection_report.hpp"

namespace gdnav::nav {

// Through the GNSS-aided phase nav_att publishes the paper's attitude filter (kPaper), or the joint GNSS/INS estimator
// that hands over to that filter at the GNSS loss (kGnssIns; variant key `aided_attitude: gnss_ins`, docs/navigation.md,
// "Keeping the GNSS calibration").
enum class AidedAttitude { kPaper, kGnssIns };
// After the GNSS loss nav_att publishes the paper's attitude filter, started from the estimator's hand-over (kPaper),
// or the joint estimator goes on, on air data and the magnetometer (kGnssIns; variant key `denied_attitude: gnss_ins`,
// which needs `aided_attitude: gnss_ins`).
enum class DeniedAttitude { kPaper, kGnssIns };

// The tuning file holds one section per filter (air, attitude, position) and a variant file one per filter it changes
// (attitude, position), the optional `aided_attitude` and `denied_attitude` and, with `aided_attitude: gnss_ins`, the
// optional `gnss_ins` section (the joint estimator's settings, the keys of `in_flight_alignment`). Each file is
// validated whole wherever it is read: every section is parsed by its filter's parser and finish() runs on the whole
// file, so an unknown or misspelt key anywhere in it — also at the top level or in another filter's section — is an
// error, whichever nav components the run has.
struct NavFiles {
    config::Config tuning;   // the whole tuning file
    config::Config variant;  // the whole variant file
    AidedAttitude aided{AidedAttitude::kPaper};
    DeniedAttitude denied{DeniedAttitude::kPaper};
    InFlightAlignerSettings gnss_ins;  // the variant's `gnss_ins` section over the defaults
    double gnss_loss_timeout_s{0.0};  // the position filter's (tuning `position.gnss_loss_timeout_s`)
};
NavFiles load_nav_files(const config::Config& cfg, bool has_variant);

// The component's `init_mode: measurements | alignment`, if given (it overrides the tuning file's).
std::optional<InitMode> init_override(const config::Config& cfg);

// A nav component around one filter; its rejections are by default the filter's and those before initialisation.
template <class Filter>
class FilterComponent : public RejectionReporting {
public:
    using RejectionReporting::RejectionReporting;

protected:
    [[nodiscard]] std::uint64_t total() const override {
        return filter_.rejections().total() + rejected_before_init();
    }

    Filter filter_;
};

// nav_att and nav_pos: a filter that has a variant, configured from its `Section` of both nav files, then with the
// component's `init_mode` override, if any. Returns the files for what else the component reads of them.
template <class Filter, const char* Section>
class VariantFilterComponent : public FilterComponent<Filter> {
public:
    using FilterComponent<Filter>::FilterComponent;

protected:
    NavFiles configure_filter(const config::Config& cfg, rnd::Stream& stream) {
        NavFiles files = load_nav_files(cfg, true);
        this->filter_.configure(files.tuning.child(Section), files.variant.child(Section), stream.child("filter"));
        if (auto m = init_override(cfg)) {
            typename Filter::Tuning t = this->filter_.tuning();
            t.init_mode = *m;
            this->filter_.configure(t, stream.child("filter"));
        }
        return files;
    }
};

inline constexpr char kAttitudeSection[] = "attitude";
inline constexpr char kPositionSection[] = "position";

// Registration, one per component file.
void register_nav_air(framework::ComponentRegistry& reg);
void register_nav_att(framework::ComponentRegistry& reg);
void register_nav_pos(framework::ComponentRegistry& reg);

}  // namespace gdnav::nav
