#include "io/flight_log/log_layout.hpp"

#include "msgs/messages.hpp"

namespace gdnav::io::flight_log {

#define GDNAV_LOG_SCALAR(M, f) LogField{#f, [](void* p) -> double& { return static_cast<M*>(p)->f(); }}
#define GDNAV_LOG_ELEM(M, f, i) LogField{#f "_" #i, [](void* p) -> double& { return static_cast<M*>(p)->f()[i]; }}
#define GDNAV_LOG_VEC3(M, f) GDNAV_LOG_ELEM(M, f, 0), GDNAV_LOG_ELEM(M, f, 1), GDNAV_LOG_ELEM(M, f, 2)
#define GDNAV_LOG_TIME(M) [](void* p) -> double& { return static_cast<M*>(p)->stamp().t_s(); }

const std::vector<LogGroup>& log_groups() {
    using namespace gdnav::msg;
    static const std::vector<LogGroup> groups{
        {"imu", topics::kImu, {GDNAV_LOG_VEC3(ImuSample, f_b_mps2), GDNAV_LOG_VEC3(ImuSample, w_b_rps)}, false,
         GDNAV_LOG_TIME(ImuSample)},
        {"mag", topics::kMag, {GDNAV_LOG_VEC3(MagSample, b_b_nT)}, false, GDNAV_LOG_TIME(MagSample)},
        {"air", topics::kAir,
         {GDNAV_LOG_SCALAR(AirSample, tas_mps), GDNAV_LOG_SCALAR(AirSample, aoa_rad), GDNAV_LOG_SCALAR(AirSample, aos_rad)},
         false, GDNAV_LOG_TIME(AirSample)},
        {"atm", topics::kAtm, {GDNAV_LOG_SCALAR(AtmSample, p_Pa), GDNAV_LOG_SCALAR(AtmSample, T_K)}, false,
         GDNAV_LOG_TIME(AtmSample)},
        {"gnss", topics::kGnss,
         {GDNAV_LOG_SCALAR(GnssSample, lon_rad), GDNAV_LOG_SCALAR(GnssSample, lat_rad), GDNAV_LOG_SCALAR(GnssSample, h_m),
          GDNAV_LOG_VEC3(GnssSample, v_n_mps)},
         true, GDNAV_LOG_TIME(GnssSample), [](void* p) -> bool& { return static_cast<GnssSample*>(p)->fix_valid(); }},
    };
    return groups;
}

const AlignmentLayout& alignment_layout() {
    using namespace gdnav::msg;
    static const AlignmentLayout layout{
        {GDNAV_LOG_ELEM(ImuSample, align_q_nb, 0), GDNAV_LOG_ELEM(ImuSample, align_q_nb, 1),
         GDNAV_LOG_ELEM(ImuSample, align_q_nb, 2), GDNAV_LOG_ELEM(ImuSample, align_q_nb, 3),
         GDNAV_LOG_SCALAR(ImuSample, align_att_sigma_rad), GDNAV_LOG_VEC3(ImuSample, align_gyr_err_rps),
         GDNAV_LOG_VEC3(ImuSample, align_gyr_err_sigma_rps), GDNAV_LOG_VEC3(ImuSample, align_acc_err_mps2),
         GDNAV_LOG_VEC3(ImuSample, align_acc_err_sigma_mps2)},
        {GDNAV_LOG_VEC3(MagSample, align_mag_err_nT), GDNAV_LOG_VEC3(MagSample, align_mag_err_sigma_nT),
         GDNAV_LOG_VEC3(MagSample, align_b_dev_n_nT), GDNAV_LOG_VEC3(MagSample, align_b_dev_sigma_nT)},
    };
    return layout;
}

#undef GDNAV_LOG_SCALAR
#undef GDNAV_LOG_ELEM
#undef GDNAV_LOG_VEC3
#undef GDNAV_LOG_TIME

}  // namespace gdnav::io::flight_log
