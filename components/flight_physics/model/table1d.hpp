#pragma once
// One-dimensional table with C1 "biparabolic" interpolation: inside [x_i, x_i+1] the value is the linear blend
// (1 - t) q_L(x) + t q_R(x), t = (x - x_i) / (x_i+1 - x_i), of the parabola through knots (i-1, i, i+1) and the one
// through (i, i+1, i+2); at the first and last interval only the existing parabola is used. Outside the knots the
// table extrapolates linearly with the end value and end slope. Two knots give plain linear interpolation.
// This is the interpolation the reference applies to its aerodynamic tables; we use it for every 1-D table.
// The value is linear in the knot values: value(x) = sum_j w_j(x) y_first+j over at most four knots (a Stencil),
// so several tables on the same knots can share one stencil (see Aerodynamics).
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace gdnav::physics {

class Table1D {
public:
    struct Stencil {
        std::size_t first{0};
        std::array<double, 4> w{};
    };

    Table1D() = default;
    // Knots must be strictly increasing, at least two, same count as values (throws std::invalid_argument).
    Table1D(std::vector<double> x, std::vector<double> y);

    [[nodiscard]] double operator()(double x) const { return apply(stencil(x)); }
    // (value, dvalue/dx)
    [[nodiscard]] std::pair<double, double> eval(double x) const;
    [[nodiscard]] Stencil stencil(double x) const;
    [[nodiscard]] double apply(const Stencil& s) const {
        const double* y = y_.data() + s.first;
        return s.w[0] * y[0] + s.w[1] * y[1] + s.w[2] * y[2] + s.w[3] * y[3];
    }
    [[nodiscard]] const std::vector<double>& x() const { return x_; }
    [[nodiscard]] const std::vector<double>& y() const { return y_; }

private:
    [[nodiscard]] std::size_t interval(double x) const;
    // Value weights (on knots k, k+1, k+2) and slope weights of the parabola through those knots at x.
    void parabola(std::size_t k, double x, double* w, double* dw) const;
    // Weights of value and slope inside interval i, on knots i-1 .. i+2 (first = max(i, 1) - 1).
    void inside(std::size_t i, double x, Stencil& value, Stencil& slope) const;

    std::vector<double> x_, y_;  // y_ padded with zeros so a stencil may always read four values
    std::size_t n_{0};
    Stencil slope_lo_{}, slope_hi_{};  // slope weights at the end knots
};

}  // namespace gdnav::physics
