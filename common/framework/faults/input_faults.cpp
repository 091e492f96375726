#include "framework/faults/input_faults.hpp"

#include <algorithm>
#include <limits>

namespace gdnav::framework::faults {

InputFaults::InputFaults(const FaultSchedule& schedule, const std::string& topic, std::vector<std::string> producers,
                         const msg::MessageOps& ops, const RunInfo& run)
    : schedule_(schedule), topic_(topic), producers_(std::move(producers)), ops_(ops), run_(run) {
    extend(0);
}

void InputFaults::extend(std::size_t first) {
    const fields::TypeFields* table = fields::find_type_fields(ops_.type_name);
    std::uint64_t history = history_.size();
    for (const auto& p : producers_) {
        for (const Fault* f : schedule_.on(p, topic_, first)) {
            Active a{f, rnd::Stream::derive(run_.seed, run_.run_index, f->target), {}, nullptr, false};
            for (const auto& [name, values] : f->fields)
                for (std::size_t i = 0; table && i < table->count; ++i)
                    if (name == table->fields[i].name) a.fields.emplace_back(&table->fields[i], values);
            if (f->kind == Kind::Freeze) a.frozen = ops_.create();
            if (f->kind == Kind::Delay) history = std::max(history, f->delay_steps + 1);
            faults_.push_back(std::move(a));
        }
    }
    std::sort(faults_.begin(), faults_.end(), [](const Active& a, const Active& b) {
        return a.fault->index < b.fault->index;
    });
    if (history > history_.size()) {
        // A longer ring: samples already held move to their slots in it.
        std::vector<void*> ring;
        std::vector<std::uint64_t> steps(history, 0);
        std::vector<bool> full(history, false);
        for (std::uint64_t i = 0; i < history; ++i) ring.push_back(ops_.create());
        for (std::size_t i = 0; i < history_.size(); ++i) {
            if (history_full_[i]) {
                const std::size_t n = history_step_[i] % history;
                ops_.copy(ring[n], history_[i]);
                steps[n] = history_step_[i];
                full[n] = true;
            }
            ops_.destroy(history_[i]);
        }
        history_ = std::move(ring);
        history_step_ = std::move(steps);
        history_full_ = std::move(full);
    }
}

InputFaults::~InputFaults() {
    for (auto& a : faults_) ops_.destroy(a.frozen);
    for (void* h : history_) ops_.destroy(h);
    ops_.destroy(out_);
}

bool InputFaults::producer_killed(std::uint64_t j) const {
    if (faults_.empty() || producers_.empty()) return false;
    for (const auto& p : producers_)
        if (!schedule_.killed(p, j)) return false;
    return true;
}

void* InputFaults::scratch() {
    if (!out_) out_ = ops_.create();
    return out_;
}

void InputFaults::add_to_fields(const Active& a, void* msg, std::uint64_t j) {
    rnd::Stream s = a.stream.child("fault" + std::to_string(a.fault->index) + "/" + std::to_string(j));
    for (const auto& [field, values] : a.fields) {
        auto* x = static_cast<double*>(field->ptr(msg));
        for (std::size_t e = 0; e < field->count; ++e) {
            const double v = values.size() == 1 ? values[0] : values[e];
            x[e] += a.fault->kind == Kind::Bias ? v : v * s.normal();
        }
    }
}

void InputFaults::set_nan(const Active& a, void* msg) {
    for (const auto& entry : a.fields) {
        auto* x = static_cast<double*>(entry.first->ptr(msg));
        for (std::size_t e = 0; e < entry.first->count; ++e) x[e] = std::numeric_limits<double>::quiet_NaN();
    }
}

InputFaults::Delivery InputFaults::apply(std::uint64_t j, const void* sample) {
    if (j == memo_step_) return memo_;
    memo_step_ = j;
    const bool killed = producer_killed(j);
    if (killed || !sample) return memo_ = {nullptr, killed};
    if (!history_.empty()) {
        const std::size_t i = j % history_.size();
        ops_.copy(history_[i], sample);
        history_step_[i] = j;
        history_full_[i] = true;
    }
    for (auto& a : faults_)
        if (a.frozen && j < a.fault->from_step) {
            ops_.copy(a.frozen, sample);
            a.have_frozen = true;
        }
    const void* cur = sample;
    for (auto& a : faults_) {
        const Fault& f = *a.fault;
        if (!f.active(j)) continue;
        switch (f.kind) {
            case Kind::Drop: return memo_ = {nullptr, false};
            case Kind::Loss: {
                rnd::Stream s = a.stream.child("fault" + std::to_string(f.index) + "/" + std::to_string(j));
                if (s.uniform() < f.probability) return memo_ = {nullptr, false};
                break;
            }
            case Kind::Delay: {
                if (j < f.delay_steps) return memo_ = {nullptr, false};
                const std::size_t i = (j - f.delay_steps) % history_.size();
                if (!history_full_[i] || history_step_[i] != j - f.delay_steps) return memo_ = {nullptr, false};
                cur = history_[i];
                break;
            }
            case Kind::Freeze: {
                if (!a.have_frozen) return memo_ = {nullptr, false};  // frozen from the first step: nothing to repeat
                void* o = scratch();
                ops_.copy(o, a.frozen);
                ops_.set_stamp(o, run_.run_index, j, run_.time_of(j));
                cur = o;
                break;
            }
            case Kind::Bias:
            case Kind::Noise: {
                void* o = scratch();
                if (cur != o) ops_.copy(o, cur);
                add_to_fields(a, o, j);
                cur = o;
                break;
            }
            case Kind::Nan: {
                void* o = scratch();
                if (cur != o) ops_.copy(o, cur);
                set_nan(a, o);
                cur = o;
                break;
            }
            case Kind::Kill:
            case Kind::Restart:
            case Kind::Rejoin: break;  // handled by producer_killed and by the hosts
        }
    }
    return memo_ = {cur, false};
}

}  // namespace gdnav::framework::faults
