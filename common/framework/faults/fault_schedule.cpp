#include "framework/faults/fault_schedule.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "framework/fields/field_table.hpp"
#include "framework/topic_types.hpp"

namespace gdnav::framework::faults {

using config::Config;
using config::ConfigError;
using config::Range;

namespace {

const std::vector<std::string> kKindNames{"drop", "freeze",  "bias", "noise",  "delay",
                                          "loss", "kill",    "restart", "nan", "rejoin"};

std::uint64_t step_at(double t_s, const RunInfo& run) {
    const double x = std::ceil((t_s - run.t0_s) / run.dt_s - 1e-9);
    return x <= 0.0 ? 0 : static_cast<std::uint64_t>(x);
}

std::string seconds(double t) { return fmt::format("{:g} s", t); }

[[noreturn]] void fail_at(const std::string& origin, std::size_t i, const std::string& key, const std::string& what) {
    throw ConfigError("config error: " + origin + ": key 'faults[" + std::to_string(i) + "]" +
                      (key.empty() ? "" : "." + key) + "': " + what);
}

// The field table of a topic's type (nullptr for an unknown topic or a type without a table).
const fields::TypeFields* table_of(const std::string& topic) {
    const msg::MessageOps* ops = find_topic(topic);
    return ops ? fields::find_type_fields(ops->type_name) : nullptr;
}

std::string double_fields(const fields::TypeFields& t) {
    std::string s;
    for (std::size_t i = 0; i < t.count; ++i) {
        const auto& f = t.fields[i];
        if (f.kind != fields::Kind::F64 || std::string_view(f.name).rfind("stamp.", 0) == 0) continue;
        if (!s.empty()) s.append(", ");
        s.append(f.name);
        if (f.count > 1) s.append(fmt::format("[{}]", f.count));
    }
    return s;
}

Fault parse_one(const Config& c, std::size_t i, const RunInfo& run) {
    Fault f;
    f.index = i;
    const double t_end = run.time_of(run.steps == 0 ? 0 : run.steps - 1);
    f.kind = static_cast<Kind>(std::find(kKindNames.begin(), kKindNames.end(), c.get_choice("kind", kKindNames)) -
                               kKindNames.begin());
    f.target = c.get_string("target");
    if (f.target.empty()) c.fail("target", "must name a member of the run");
    f.topic = c.get_string("topic", "");
    f.at_s = c.get_double("at_s", Range{run.t0_s, t_end});
    f.from_step = step_at(f.at_s, run);
    if (c.has("until_s")) {
        if (f.kind == Kind::Restart || f.kind == Kind::Rejoin)
            c.fail("until_s", std::string("a ") + kind_name(f.kind) + " has no end (remove until_s)");
        f.until_s = c.get_double("until_s", Range{std::nextafter(f.at_s, 1e300), 1e9});
        f.has_until = true;
        f.until_step = std::max(step_at(f.until_s, run), f.from_step + 1);
    }
    if (f.kind == Kind::Restart || f.kind == Kind::Rejoin) f.until_step = f.from_step + 1;
    if (f.kind == Kind::Bias || f.kind == Kind::Noise) {
        const Config fc = c.child("fields");
        const auto names = fc.keys();
        if (names.empty()) c.fail("fields", "name at least one field: {field: value} or {field: [v1, v2, v3]}");
        const Range r = f.kind == Kind::Bias ? Range{-1e12, 1e12} : Range{0.0, 1e12};
        for (const auto& n : names) {
            std::vector<double> v;
            if (fc.node()[n].IsSequence())
                v = fc.get_doubles(n, 1, 64, r);
            else
                v.push_back(fc.get_double(n, r));
            f.fields.emplace_back(n, std::move(v));
        }
    }
    if (f.kind == Kind::Nan) {
        const auto names = c.get_strings("fields");
        if (names.empty()) c.fail("fields", "name at least one field: [field, ...]");
        for (const auto& n : names) f.fields.emplace_back(n, std::vector<double>{});
    }
    if (f.kind == Kind::Delay) f.delay_steps = static_cast<std::uint64_t>(c.get_int("steps", 1, 1000));
    if (f.kind == Kind::Loss) f.probability = c.get_double("p", Range{0.0, 1.0});
    c.finish();
    return f;
}

}  // namespace

const char* kind_name(Kind k) { return kKindNames[static_cast<std::size_t>(k)].c_str(); }

std::string Fault::describe() const {
    std::string s = std::string(kind_name(kind)) + " of " + target + (topic.empty() ? "" : " " + topic);
    if (kind == Kind::Restart || kind == Kind::Rejoin) return s + " at " + seconds(at_s);
    s += " from " + seconds(at_s);
    if (has_until) s += " to " + seconds(until_s);
    return s;
}

FaultSchedule FaultSchedule::parse(const Config& doc, const RunInfo& run) {
    FaultSchedule s;
    if (!doc.has("faults")) return s;
    if (doc.node()["faults"].IsNull()) {
        (void)doc.keys();
        return s;
    }
    const auto items = doc.items("faults");
    for (std::size_t i = 0; i < items.size(); ++i) s.faults_.push_back(parse_one(items[i], i, run));
    // A kill without until_s lasts until the first later restart of its target; a restart needs such a kill.
    const std::string& origin = doc.origin();
    for (auto& f : s.faults_) {
        if (f.kind != Kind::Restart) continue;
        Fault* kill = nullptr;
        for (auto& k : s.faults_)
            if (k.kind == Kind::Kill && k.target == f.target && k.from_step < f.from_step && !k.has_until &&
                (!kill || k.from_step > kill->from_step))
                kill = &k;
        if (!kill)
            fail_at(origin, f.index, "kind", "restart of '" + f.target + "' at " + seconds(f.at_s) +
                                                 ": no kill of '" + f.target + "' without until_s before it");
        if (kill->until_step != UINT64_MAX)
            fail_at(origin, f.index, "kind", "'" + f.target + "' is restarted twice after the kill at " +
                                                 seconds(kill->at_s));
        kill->until_step = f.from_step;
    }
    for (const auto& a : s.faults_)
        for (const auto& b : s.faults_)
            if (&a != &b && a.kind == Kind::Kill && b.kind == Kind::Kill && a.target == b.target &&
                b.from_step < a.until_step && (a.from_step < b.from_step || (a.from_step == b.from_step && a.index < b.index)))
                fail_at(origin, b.index, "at_s", "'" + b.target + "' is already killed then (by faults[" +
                                                     std::to_string(a.index) + "])");
    return s;
}

FaultSchedule FaultSchedule::from_yaml(const std::string& text, const RunInfo& run) {
    if (text.empty()) return {};
    const Config doc = Config::parse(text, "the fault schedule of the clock's CONFIGURE");
    FaultSchedule s = parse(doc, run);
    doc.finish();
    return s;
}

std::string FaultSchedule::to_yaml() const {
    if (faults_.empty()) return "";
    YAML::Emitter em;
    em.SetDoublePrecision(17);
    em << YAML::Flow << YAML::BeginMap << YAML::Key << "faults" << YAML::Value << YAML::BeginSeq;
    for (const auto& f : faults_) {
        em << YAML::BeginMap << YAML::Key << "kind" << YAML::Value << kind_name(f.kind);
        em << YAML::Key << "target" << YAML::Value << f.target;
        if (!f.topic.empty()) em << YAML::Key << "topic" << YAML::Value << f.topic;
        em << YAML::Key << "at_s" << YAML::Value << f.at_s;
        if (f.has_until) em << YAML::Key << "until_s" << YAML::Value << f.until_s;
        if (f.kind == Kind::Nan) {
            em << YAML::Key << "fields" << YAML::Value << YAML::BeginSeq;
            for (const auto& [n, _] : f.fields) em << n;
            em << YAML::EndSeq;
        } else if (!f.fields.empty()) {
            em << YAML::Key << "fields" << YAML::Value << YAML::BeginMap;
            for (const auto& [n, v] : f.fields) {
                em << YAML::Key << n << YAML::Value << YAML::BeginSeq;
                for (double x : v) em << x;
                em << YAML::EndSeq;
            }
            em << YAML::EndMap;
        }
        if (f.kind == Kind::Delay) em << YAML::Key << "steps" << YAML::Value << f.delay_steps;
        if (f.kind == Kind::Loss) em << YAML::Key << "p" << YAML::Value << f.probability;
        em << YAML::EndMap;
    }
    em << YAML::EndSeq << YAML::EndMap;
    return em.c_str();
}

void FaultSchedule::validate(const std::map<std::string, MemberPorts>& members, const std::string& origin) const {
    for (const auto& f : faults_) {
        const auto it = members.find(f.target);
        if (it == members.end()) {
            std::string known;
            for (const auto& [n, _] : members) known += (known.empty() ? "" : ", ") + n;
            fail_at(origin, f.index, "target", "'" + f.target + "' is not a member of this run (members: " + known + ")");
        }
        const MemberPorts& m = it->second;
        if (m.external && (f.kind == Kind::Restart || (f.kind == Kind::Kill && f.until_step != UINT64_MAX)))
            fail_at(origin, f.index, "kind", "'" + f.target + "' is an external member: gdnav cannot restart it");
        if (f.kind == Kind::Kill || f.kind == Kind::Restart || f.kind == Kind::Rejoin) {
            if (!f.topic.empty()) fail_at(origin, f.index, "topic", "a " + std::string(kind_name(f.kind)) +
                                                                        " acts on the member, not on one topic");
            continue;
        }
        if (!f.topic.empty() && !m.external &&
            std::find(m.outputs.begin(), m.outputs.end(), f.topic) == m.outputs.end()) {
            std::string outs;
            for (const auto& o : m.outputs) outs += (outs.empty() ? "" : ", ") + o;
            fail_at(origin, f.index, "topic", "'" + f.topic + "' is not an output of '" + f.target + "' (outputs: " +
                                                  (outs.empty() ? "none" : outs) + ")");
        }
        if (f.fields.empty()) continue;
        std::string topic = f.topic;
        if (topic.empty()) {
            if (m.external || m.outputs.size() != 1)
                fail_at(origin, f.index, "topic", "required for a " + std::string(kind_name(f.kind)) + " of '" +
                                                      f.target + "' (which topic's fields?)");
            topic = m.outputs.front();
        }
        const fields::TypeFields* t = table_of(topic);
        if (!t) fail_at(origin, f.index, "topic", "'" + topic + "' has no field table (unknown topic)");
        for (const auto& [name, v] : f.fields) {
            const fields::Field* field = nullptr;
            for (std::size_t i = 0; i < t->count; ++i)
                if (name == t->fields[i].name) field = &t->fields[i];
            if (!field || field->kind != fields::Kind::F64 || name.rfind("stamp.", 0) == 0)
                fail_at(origin, f.index, "fields." + name, "not a number field of " + topic + " (fields: " +
                                                               double_fields(*t) + ")");
            if (f.kind != Kind::Nan && v.size() != 1 && v.size() != field->count)
                fail_at(origin, f.index, "fields." + name, "give 1 value or " + std::to_string(field->count) +
                                                               " (one per element), not " + std::to_string(v.size()));
        }
    }
}

std::vector<const Fault*> FaultSchedule::on(const std::string& producer, const std::string& topic,
                                            std::size_t first) const {
    std::vector<const Fault*> v;
    for (std::size_t i = first; i < faults_.size(); ++i)
        if (faults_[i].kind != Kind::Restart && faults_[i].kind != Kind::Rejoin &&
            faults_[i].applies_to(producer, topic))
            v.push_back(&faults_[i]);
    return v;
}

const Fault& FaultSchedule::add_live(const std::string& entry_yaml, std::uint64_t at_step, const RunInfo& run,
                                     const std::map<std::string, MemberPorts>& members) {
    const std::string origin = "fault request";
    YAML::Node e;
    try {
        e = YAML::Load(entry_yaml);
    } catch (const YAML::Exception& ex) {
        throw ConfigError("config error: " + origin + ": malformed YAML: " + ex.msg);
    }
    if (!e.IsMap()) throw ConfigError("config error: " + origin + ": must be a mapping {target: ..., kind: ...}");
    if (e["at_s"]) throw ConfigError("config error: " + origin + ": key 'at_s': set by the clock (remove it)");
    const double at_s = run.time_of(at_step);
    e["at_s"] = at_s;
    if (e["duration_s"]) {
        const Config d = Config::wrap(e, origin);
        const double dur = d.get_double("duration_s", Range{run.dt_s, 1e9});
        e.remove("duration_s");
        e["until_s"] = at_s + dur;
    }
    YAML::Node doc;
    doc["faults"].push_back(e);
    const Config c = Config::wrap(doc, origin);
    FaultSchedule one = parse(c, run);
    Fault f = one.faults_.front();
    if (f.kind == Kind::Restart)
        throw ConfigError("config error: " + origin + ": key 'kind': restart cannot be injected live (give the kill a "
                          "duration_s instead)");
    // (rejoin: added by the clock itself when a dead member comes back)
    one.validate(members, origin);
    for (const auto& k : faults_)
        if (f.kind == Kind::Kill && k.kind == Kind::Kill && k.target == f.target && k.active(f.from_step))
            throw ConfigError("config error: " + origin + ": '" + f.target + "' is already killed then");
    f.index = faults_.size();
    faults_.push_back(f);
    return faults_.back();
}

std::size_t FaultSchedule::adopt(const FaultSchedule& longer) {
    const std::size_t first = faults_.size();
    for (std::size_t i = first; i < longer.faults_.size(); ++i) faults_.push_back(longer.faults_[i]);
    return first;
}

bool FaultSchedule::killed(const std::string& member, std::uint64_t k) const {
    for (const auto& f : faults_)
        if (f.kind == Kind::Kill && f.target == member && f.active(k)) return true;
    return false;
}

bool FaultSchedule::restarts_at(const std::string& member, std::uint64_t k) const {
    for (const auto& f : faults_)
        if (f.kind == Kind::Kill && f.target == member && f.until_step == k) return true;
    return false;
}

std::uint64_t FaultSchedule::alive_again(const std::string& member, std::uint64_t k) const {
    while (killed(member, k)) {
        std::uint64_t next = UINT64_MAX;
        for (const auto& f : faults_)
            if (f.kind == Kind::Kill && f.target == member && f.active(k)) next = std::min(next, f.until_step);
        if (next == UINT64_MAX) return UINT64_MAX;
        k = next;
    }
    return k;
}

}  // namespace gdnav::framework::faults
