#include "runtime/direct_executor.hpp"

#include <chrono>
#include <map>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "runtime/graph.hpp"

namespace gdnav::runtime {

DirectExecutor::DirectExecutor(std::vector<std::unique_ptr<Component>> components, const RunInfo& run)
    : owned_(std::move(components)), run_(run) {
    std::vector<Component*> raw;
    for (auto& c : owned_) raw.push_back(c.get());
    const Graph g = build_graph(raw);
    order_ = g.order;
    std::map<std::string, PrevBuffer*> prev_by_topic;
    for (Component* c : order_) {
        std::vector<Binding> b;
        for (InputBase* in : c->inputs()) {
            auto it = g.producer.find(in->topic());
            if (it == g.producer.end())
                throw std::runtime_error("component '" + c->name() + "' reads topic '" + in->topic() +
                                         "' that no component of this run produces");
            if (in->lag() == Lag::Same) {
                b.push_back({in, it->second->data(), nullptr});
            } else {
                PrevBuffer*& pb = prev_by_topic[in->topic()];
                if (!pb) {
                    prev_.push_back(std::make_unique<PrevBuffer>(
                        PrevBuffer{it->second, it->second->ops().create(), false}));
                    pb = prev_.back().get();
                }
                b.push_back({in, nullptr, pb});
            }
        }
        bindings_.push_back(std::move(b));
    }
}

DirectExecutor::~DirectExecutor() {
    for (auto& p : prev_) p->source->ops().destroy(p->copy);
}

void DirectExecutor::step(std::uint64_t k) {
    StepContext ctx{k, run_.time_of(k), run_.dt_s, k + 1 == run_.steps};
    for (std::size_t i = 0; i < order_.size(); ++i) {
        Component* c = order_[i];
        for (const Binding& b : bindings_[i]) {
            if (b.previous)
                b.input->bind(b.previous->valid ? b.previous->copy : nullptr);
            else
                b.input->bind(b.same);
        }
        if (profile_ns_.empty()) {
            c->step(ctx);
        } else {
            const auto t0 = std::chrono::steady_clock::now();
            c->step(ctx);
            profile_ns_[i] += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
        }
        for (OutputBase* o : c->outputs()) o->ops().set_stamp(o->data(), run_.run_index, k, ctx.t_s);
        for (auto& msg : c->pending_status()) spdlog::info("[{}] step {} t={:.2f} s: {}", c->name(), k, ctx.t_s, msg);
        c->pending_status().clear();
    }
    for (auto& p : prev_) {
        p->source->ops().copy(p->copy, p->source->data());
        p->valid = true;
    }
}

std::uint64_t DirectExecutor::run(const std::function<bool(std::uint64_t)>& progress, std::uint64_t every) {
    std::uint64_t k = 0;
    for (; k < run_.steps; ++k) {
        step(k);
        if (progress && (k + 1) % every == 0 && !progress(k + 1)) {
            finish(false);
            return k + 1;
        }
    }
    finish(true);
    return k;
}

std::vector<double> DirectExecutor::mean_step_us(std::uint64_t steps) const {
    std::vector<double> v;
    for (auto ns : profile_ns_) v.push_back(static_cast<double>(ns) * 1e-3 / static_cast<double>(std::max<std::uint64_t>(steps, 1)));
    return v;
}

void DirectExecutor::finish(bool completed) {
    if (finished_) return;
    finished_ = true;
    for (Component* c : order_) c->finish(completed);
}

}  // namespace gdnav::runtime
