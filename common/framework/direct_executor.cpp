#include "framework/direct_executor.hpp"

#include <chrono>
#include <exception>
#include <stdexcept>

#include <spdlog/spdlog.h>

#include "files/write_error.hpp"
#include "framework/executor_access.hpp"
#include "framework/stride_policy.hpp"
#include "framework/graph.hpp"

namespace gdnav::framework {

DirectExecutor::DirectExecutor(std::vector<std::unique_ptr<Component>> components, const RunInfo& run)
    : owned_(std::move(components)), run_(run) {
    std::vector<Component*> raw;
    for (auto& c : owned_) raw.push_back(c.get());
    order_ = build_graph(raw).order;
    killed_.assign(order_.size(), false);
    bind_all();
}

DirectExecutor::~DirectExecutor() {
    for (auto& [_, p] : prev_) p->source->ops().destroy(p->copy);
}

// (Re)binds every input to its producer: at the start, and after a member was created anew by a restart. Buffers
// of step k-1 and the inputs' fault state survive a rebind (keyed by topic and by consumer input).
void DirectExecutor::bind_all() {
    std::map<std::string, std::pair<OutputBase*, Component*>> producer;
    for (Component* c : order_)
        for (OutputBase* o : c->outputs()) producer[o->topic()] = {o, c};
    bindings_.clear();
    for (Component* c : order_) {
        std::vector<Binding> b;
        for (std::size_t n = 0; n < c->inputs().size(); ++n) {
            InputBase* in = c->inputs()[n];
            auto it = producer.find(in->topic());
            if (it == producer.end())
                throw std::runtime_error("component '" + c->name() + "' reads topic '" + in->topic() +
                                         "' that no component of this run produces");
            OutputBase* out = it->second.first;
            faults::InputFaults* f = nullptr;
            if (schedule_) {
                auto& slot = input_faults_[c->name() + "/" + std::to_string(n)];
                if (!slot)
                    slot = std::make_unique<faults::InputFaults>(*schedule_, in->topic(),
                                                                 std::vector<std::string>{it->second.second->name()},
                                                                 in->ops(), run_);
                if (!slot->empty()) f = slot.get();
            }
            if (in->lag() == Lag::Same) {
                b.push_back({in, out, nullptr, f});
            } else {
                auto& pb = prev_[in->topic()];
                if (!pb) pb = std::make_unique<PrevBuffer>(PrevBuffer{out, out->ops().create(), false});
                pb->source = out;
                b.push_back({in, nullptr, pb.get(), f});
            }
        }
        bindings_.push_back(std::move(b));
    }
}

void DirectExecutor::set_faults(const faults::FaultSchedule& schedule, Factory rebuild) {
    if (schedule.empty()) return;
    schedule_ = &schedule;
    rebuild_ = std::move(rebuild);
    input_faults_.clear();
    bind_all();
}

void DirectExecutor::restart(std::size_t i, std::uint64_t k) {
    if (!rebuild_) throw std::runtime_error("member '" + order_[i]->name() + "' cannot be restarted (no factory)");
    const std::string name = order_[i]->name();
    std::unique_ptr<Component> fresh = rebuild_(name);
    for (auto& c : owned_)
        if (c.get() == order_[i]) c = std::move(fresh), order_[i] = c.get();
    killed_[i] = false;
    bind_all();
    spdlog::warn("[{}] step {} t={:.2f} s: restarted by a scheduled fault (created anew)", name, k, run_.time_of(k));
}

void DirectExecutor::step(std::uint64_t k) {
    StepContext ctx{k, run_.time_of(k), run_.dt_s, k + 1 == run_.steps};
    for (std::size_t i = 0; i < order_.size(); ++i) {
        if (schedule_) {
            if (schedule_->restarts_at(order_[i]->name(), k)) restart(i, k);
            const bool killed = schedule_->killed(order_[i]->name(), k);
            if (killed && !killed_[i])
                spdlog::warn("[{}] step {} t={:.2f} s: killed by a scheduled fault", order_[i]->name(), k, ctx.t_s);
            killed_[i] = killed;
            if (killed) continue;
        }
        Component* c = order_[i];
        for (const Binding& b : bindings_[i]) {
            if (!on_stride(*b.input, b.previous ? k - 1 : k)) {  // not a step it reads (framework/stride_policy.hpp)
                ExecutorAccess::bind(*b.input, nullptr);
                continue;
            }
            const void* data = b.previous ? (b.previous->valid ? b.previous->copy : nullptr) : b.producer->data();
            if (b.faults && (b.previous == nullptr || k > 0)) {
                const auto d = b.faults->apply(b.previous ? k - 1 : k, data);
                ExecutorAccess::set_lost(*b.input, d.lost);
                data = d.data;
            }
            ExecutorAccess::bind(*b.input, data);
        }
        try {
            if (profile_ns_.empty()) {
                c->step(ctx);
            } else {
                const auto t0 = std::chrono::steady_clock::now();
                c->step(ctx);
                profile_ns_[i] += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
            }
        } catch (const files::WriteError& e) {
            // The same error, with the member and the step (exit code 6: docs/runtime.md "Exit codes").
            throw files::WriteError(
                e.file(), e.os_error(), fmt::format("member '{}' failed at step {} (t = {:.2f} s): ", c->name(), k, ctx.t_s));
        } catch (const std::exception& e) {
            // Named as a DDS host names it (dds/host/host_step.cpp): the member, the step, the first line.
            std::string what = e.what();
            throw std::runtime_error(fmt::format("member '{}' failed at step {} (t = {:.2f} s): {}", c->name(), k,
                                                 ctx.t_s, what.substr(0, what.find('\n'))));
        }
        for (OutputBase* o : c->outputs()) o->ops().set_stamp(o->data(), run_.run_index, k, ctx.t_s);
        for (const auto& msg : ExecutorAccess::take_status(*c))
            spdlog::info("[{}] step {} t={:.2f} s: {}", c->name(), k, ctx.t_s, msg);
    }
    for (auto& [_, p] : prev_) {
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
    // Every member finishes (closes its files) even when another one's finish throws; the first exception is
    // rethrown afterwards, its type kept (a files::WriteError gives exit code 6).
    std::exception_ptr first;
    for (std::size_t i = 0; i < order_.size(); ++i) {
        if (killed_[i]) continue;
        try {
            order_[i]->finish(completed);
        } catch (const std::exception& e) {
            spdlog::error("member '{}' failed at the end of the run: {}", order_[i]->name(), e.what());
            if (!first) first = std::current_exception();
        }
    }
    if (first) std::rethrow_exception(first);
}

}  // namespace gdnav::framework
