#include "launch/pki/pki_identities.hpp"

#include <set>

#include "config/config.hpp"
#include "dds/security/security.hpp"
#include "msgs/messages.hpp"

namespace gdnav::launch::pki {

namespace {

std::vector<std::string> member_publish(std::vector<std::string> outputs) {
    outputs.push_back(topics::kStepDone);
    outputs.push_back(topics::kStatus);
    return outputs;
}

}  // namespace

std::vector<Identity> run_identities(const framework::RunConfig& rc, const framework::ComponentRegistry& reg,
                                     const std::vector<std::string>& external_members) {
    std::vector<Identity> ids{
        {dds::security::kClockIdentity, {topics::kTick, topics::kRunControl, topics::kStatus}},
        {dds::security::kOperatorIdentity, {topics::kFaultRequest}},
    };
    std::set<std::string> all_outputs;
    for (const auto& c : rc.build(reg)) {
        std::vector<std::string> outs;
        for (const auto* o : c->outputs()) {
            outs.push_back(o->topic());
            all_outputs.insert(o->topic());
        }
        ids.push_back({c->name(), member_publish(outs)});
    }
    std::set<std::string> names;
    for (const auto& id : ids) names.insert(id.name);
    // `gdnav run --record` adds a member `recorder` (no outputs) to any scenario.
    if (!names.count("recorder")) ids.push_back({"recorder", member_publish({})});
    ids.push_back({dds::security::kComposedIdentity, member_publish({all_outputs.begin(), all_outputs.end()})});
    names.insert("recorder");
    names.insert(dds::security::kComposedIdentity);
    for (const auto& m : external_members) {
        const auto eq = m.find('=');
        const std::string name = m.substr(0, eq);
        if (eq == std::string::npos || name.empty() || eq + 1 >= m.size())
            throw config::ConfigError("config error: --member '" + m +
                                      "': expected NAME=TOPIC[,TOPIC...] (the topics the member publishes)");
        if (!names.insert(name).second)
            throw config::ConfigError("config error: --member '" + name + "': identity already made for the scenario");
        std::vector<std::string> topics_of;
        std::string rest = m.substr(eq + 1);
        for (std::size_t p = 0; p <= rest.size();) {
            const auto c = rest.find(',', p);
            const std::string t = rest.substr(p, c == std::string::npos ? std::string::npos : c - p);
            if (!t.empty()) topics_of.push_back(t);
            if (c == std::string::npos) break;
            p = c + 1;
        }
        ids.push_back({name, member_publish(topics_of)});
    }
    return ids;
}

}  // namespace gdnav::launch::pki
