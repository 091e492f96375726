#include "sensors/model/magnetic.hpp"

#include <cmath>

namespace gdnav::sensors {

void Magnetometers::configure(const MagParams& params, rnd::Stream group_stream) {
    params_ = params;
    const rnd::Stream stream = group_stream.child("mag");
    rnd::Stream hi = stream.child("hard_iron");
    rnd::Stream off = stream.child("offset");
    rnd::Stream scale = stream.child("scale");
    noise_ = stream.child("noise");
    const MagGrade& g = params.grade;
    hard_iron_ = g.hard_iron_nT * hi.normal3();
    offset_ = g.bias_offset_nT * off.normal3();
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m_(i, j) = (i == j ? g.scale_factor : g.cross_coupling) * scale.normal();
    }
    noise_sigma_ = g.system_noise_nT_rts / std::sqrt(params.dt_s);
}

MagMeasurement Magnetometers::measure(std::uint64_t k, double t_s, const MagTruth& truth) {
    MagMeasurement out;
    out.step = k;
    out.t_s = t_s;
    const Vec3 b_b = truth.q_nb.conjugate() * truth.b_n_nT;
    out.e_mag_nT = hard_iron_ + offset_ + m_ * b_b;
    out.b_b_nT = b_b + out.e_mag_nT + noise_sigma_ * noise_.normal3();
    return out;
}

}  // namespace gdnav::sensors
