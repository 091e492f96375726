#include "flight_physics/model/table1d.hpp"

#include <algorithm>
#include <stdexcept>

namespace gdnav::physics {

Table1D::Table1D(std::vector<double> x, std::vector<double> y) : x_(std::move(x)), y_(std::move(y)) {
    if (x_.size() < 2 || x_.size() != y_.size())
        throw std::invalid_argument("Table1D: need at least two knots and as many values as knots");
    for (std::size_t i = 1; i < x_.size(); ++i)
        if (!(x_[i] > x_[i - 1])) throw std::invalid_argument("Table1D: knots must be strictly increasing");
    n_ = x_.size();
    y_.resize(n_ + 3, 0.0);
    Stencil v;
    inside(0, x_[0], v, slope_lo_);
    inside(n_ - 2, x_[n_ - 1], v, slope_hi_);
}

std::size_t Table1D::interval(double x) const {
    const auto it = std::upper_bound(x_.begin(), x_.end(), x);
    const auto i = static_cast<std::size_t>(it - x_.begin());
    return std::clamp<std::size_t>(i, 1, n_ - 1) - 1;
}

void Table1D::parabola(std::size_t k, double x, double* w, double* dw) const {
    const double x0 = x_[k], x1 = x_[k + 1], x2 = x_[k + 2];
    const double d0 = 1.0 / ((x0 - x1) * (x0 - x2));
    const double d1 = 1.0 / ((x1 - x0) * (x1 - x2));
    const double d2 = 1.0 / ((x2 - x0) * (x2 - x1));
    w[0] = (x - x1) * (x - x2) * d0;
    w[1] = (x - x0) * (x - x2) * d1;
    w[2] = (x - x0) * (x - x1) * d2;
    dw[0] = (2.0 * x - x1 - x2) * d0;
    dw[1] = (2.0 * x - x0 - x2) * d1;
    dw[2] = (2.0 * x - x0 - x1) * d2;
}

void Table1D::inside(std::size_t i, double x, Stencil& v, Stencil& s) const {
    v = {};
    s = {};
    const double h = x_[i + 1] - x_[i];
    if (n_ == 2) {
        v.first = s.first = 0;
        v.w = {(x_[1] - x) / h, (x - x_[0]) / h, 0.0, 0.0};
        s.w = {-1.0 / h, 1.0 / h, 0.0, 0.0};
        return;
    }
    const bool has_left = i >= 1;
    const bool has_right = i + 2 < n_;
    if (!has_left || !has_right) {
        const std::size_t k = has_left ? i - 1 : i;
        v.first = s.first = k;
        parabola(k, x, v.w.data(), s.w.data());
        return;
    }
    // Left parabola on knots i-1..i+1 (stencil slots 0..2), right one on i..i+2 (slots 1..3).
    double wl[3], dwl[3], wr[3], dwr[3];
    parabola(i - 1, x, wl, dwl);
    parabola(i, x, wr, dwr);
    const double t = (x - x_[i]) / h;
    v.first = s.first = i - 1;
    for (int j = 0; j < 4; ++j) {
        const double l = j < 3 ? wl[j] : 0.0, dl = j < 3 ? dwl[j] : 0.0;
        const double r = j > 0 ? wr[j - 1] : 0.0, dr = j > 0 ? dwr[j - 1] : 0.0;
        v.w[static_cast<std::size_t>(j)] = (1.0 - t) * l + t * r;
        s.w[static_cast<std::size_t>(j)] = (1.0 - t) * dl + t * dr + (r - l) / h;
    }
}

Table1D::Stencil Table1D::stencil(double x) const {
    if (x <= x_[0] || x >= x_[n_ - 1]) {
        // Linear extrapolation: y_end + slope (x - x_end); the end knot is inside the slope stencil.
        const bool lo = x <= x_[0];
        Stencil s = lo ? slope_lo_ : slope_hi_;
        const std::size_t end = lo ? 0 : n_ - 1;
        const double dx = x - x_[end];
        for (double& w : s.w) w *= dx;
        s.w[end - s.first] += 1.0;
        return s;
    }
    Stencil v, d;
    inside(interval(x), x, v, d);
    return v;
}

std::pair<double, double> Table1D::eval(double x) const {
    if (x <= x_[0]) return {y_[0] + apply(slope_lo_) * (x - x_[0]), apply(slope_lo_)};
    if (x >= x_[n_ - 1]) return {y_[n_ - 1] + apply(slope_hi_) * (x - x_[n_ - 1]), apply(slope_hi_)};
    Stencil v, d;
    inside(interval(x), x, v, d);
    return {apply(v), apply(d)};
}

}  // namespace gdnav::physics
