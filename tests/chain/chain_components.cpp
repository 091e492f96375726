#include "chain_components.hpp"

#include "runtime/topic_types.hpp"

namespace gdnav::testchain {

using config::Range;
using runtime::Input;
using runtime::Lag;
using runtime::Output;

namespace {

class Plant final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& c, const runtime::RunInfo&, rnd::Stream& s) override {
        sigma_w_ = c.get_double("sigma_w_mps2", Range::nonneg());
        damping_ = c.get_double("damping_per_s", Range::nonneg());
        x_ = c.get_double("x0_m", Range{-1e6, 1e6});
        stream_ = s;
    }
    void step(const runtime::StepContext& ctx) override {
        const double u = u_.available() ? u_.get().u_mps2() : 0.0;
        const double w = sigma_w_ * stream_.normal();
        x_ += v_ * ctx.dt_s;
        v_ += (u - damping_ * v_ + w) * ctx.dt_s;
        out_.value().x_m(x_);
        out_.value().v_mps(v_);
    }

private:
    Input<ChainControl> u_{*this, kControl, Lag::Previous};
    Output<ChainState> out_{*this, kState};
    rnd::Stream stream_;
    double sigma_w_{0}, damping_{0}, x_{0}, v_{0};
};

class Sensor final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& c, const runtime::RunInfo&, rnd::Stream& s) override {
        sigma_ = c.get_double("sigma_m", Range::nonneg());
        stream_ = s;
    }
    void step(const runtime::StepContext&) override {
        if (!in_.available()) return;  // free-running before the first state sample arrives
        out_.value().y_m(in_.get().x_m() + sigma_ * stream_.normal());
    }

private:
    Input<ChainState> in_{*this, kState};
    Output<ChainMeas> out_{*this, kMeas};
    rnd::Stream stream_;
    double sigma_{0};
};

class Filter final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& c, const runtime::RunInfo&, rnd::Stream&) override {
        alpha_ = c.get_double("alpha", Range{0.0, 1.0});
        beta_ = c.get_double("beta", Range{0.0, 1.0});
    }
    void step(const runtime::StepContext& ctx) override {
        // A lost sensor leaves the filter predicting.
        const double xp = x_ + v_ * ctx.dt_s;
        if (in_.available()) {
            const double r = in_.get().y_m() - xp;
            x_ = xp + alpha_ * r;
            v_ += beta_ * r / ctx.dt_s;
        } else {
            x_ = xp;
        }
        out_.value().x_m(x_);
        out_.value().v_mps(v_);
    }

private:
    Input<ChainMeas> in_{*this, kMeas};
    Output<ChainEstimate> out_{*this, kEstimate};
    double alpha_{0}, beta_{0}, x_{0}, v_{0};
};

class Controller final : public runtime::Component {
public:
    using Component::Component;
    void configure(const config::Config& c, const runtime::RunInfo&, rnd::Stream&) override {
        kp_ = c.get_double("kp", Range::nonneg());
        kd_ = c.get_double("kd", Range::nonneg());
        target_ = c.get_double("target_m", Range{-1e6, 1e6});
    }
    void step(const runtime::StepContext&) override {
        if (!in_.available()) return;  // no estimate (lost or dropped): hold the last command
        const auto& e = in_.get();
        out_.value().u_mps2(-kp_ * (e.x_m() - target_) - kd_ * e.v_mps());
    }

private:
    Input<ChainEstimate> in_{*this, kEstimate};
    Output<ChainControl> out_{*this, kControl};
    double kp_{0}, kd_{0}, target_{0};
};


}  // namespace

void register_chain(runtime::ComponentRegistry& reg) {
    reg.add("chain_plant", "test chain: double integrator with random disturbance", runtime::make_factory<Plant>());
    reg.add("chain_sensor", "test chain: noisy position sensor", runtime::make_factory<Sensor>());
    reg.add("chain_filter", "test chain: alpha-beta filter", runtime::make_factory<Filter>());
    reg.add("chain_controller", "test chain: PD controller", runtime::make_factory<Controller>());
    runtime::register_topic<ChainState>(kState);
    runtime::register_topic<ChainMeas>(kMeas);
    runtime::register_topic<ChainEstimate>(kEstimate);
    runtime::register_topic<ChainControl>(kControl);
}

}  // namespace gdnav::testchain
