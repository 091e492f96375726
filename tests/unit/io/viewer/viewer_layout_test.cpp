// tools/viewer/gdnav_layout.json (the Foxglove/Lichtblick layout of docs/viewing.md) names only viewer channels that
// exist and fields their schemas have, so that a layout opened on a recording never shows empty panels because of a
// renamed channel or field.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

#include "io/viewer/viewer_channels.hpp"

namespace {

const gdnav::io::viewer::ViewerChannel* channel(const std::string& topic) {
    for (const auto& c : gdnav::io::viewer::viewer_channels())
        if (c.topic == topic) return &c;
    return nullptr;
}

// Every "value" (message path TOPIC.FIELD) under a panel's config.
void collect_paths(const YAML::Node& n, std::vector<std::string>& out) {
    if (n.IsMap()) {
        for (const auto& kv : n) {
            if (kv.first.as<std::string>() == "value" && kv.second.IsScalar()) out.push_back(kv.second.as<std::string>());
            collect_paths(kv.second, out);
        }
    } else if (n.IsSequence()) {
        for (const auto& e : n) collect_paths(e, out);
    }
}

}  // namespace

TEST(ViewerLayout, PanelsNameExistingChannelsAndFields) {
    const YAML::Node layout = YAML::LoadFile(GDNAV_VIEWER_LAYOUT);  // JSON is YAML
    ASSERT_TRUE(layout["configById"].IsMap());
    ASSERT_TRUE(layout["layout"].IsMap());
    std::set<std::string> panel_types;
    std::vector<std::string> paths;
    for (const auto& kv : layout["configById"]) {
        const std::string id = kv.first.as<std::string>();
        panel_types.insert(id.substr(0, id.find('!')));
        collect_paths(kv.second, paths);
    }
    EXPECT_EQ(panel_types, (std::set<std::string>{"map", "3D", "Plot", "StateTransitions"}));
    ASSERT_GE(paths.size(), 13u);
    for (const auto& p : paths) {
        const auto dot = p.find('.');
        ASSERT_NE(dot, std::string::npos) << p;
        const auto* c = channel(p.substr(0, dot));
        ASSERT_NE(c, nullptr) << p;
        const std::string field = p.substr(dot + 1);
        EXPECT_TRUE(c->schema.find(" " + field + ";") != std::string::npos) << p << ": no such field in " << c->schema_name;
    }
    const YAML::Node map = layout["configById"]["map!gdnavmap"];
    EXPECT_NE(channel(map["followTopic"].as<std::string>()), nullptr);
    for (const auto& kv : map["topicColors"])
        EXPECT_EQ(channel(kv.first.as<std::string>())->schema_name, "foxglove::LocationFix");
    // The 3D panel's topic layers (Foxglove/Lichtblick LayerSettingsPose: visible, type axis|arrow, arrowScale, color).
    const YAML::Node three = layout["configById"]["3D!gdnav3d"]["topics"];
    ASSERT_TRUE(three.IsMap());
    EXPECT_EQ(three.size(), 2u);
    for (const auto& kv : three) {
        const auto* c = channel(kv.first.as<std::string>());
        ASSERT_NE(c, nullptr) << kv.first.as<std::string>();
        EXPECT_EQ(c->schema_name, "foxglove::PoseInFrame");
        EXPECT_TRUE(kv.second["visible"].as<bool>());
        EXPECT_EQ(kv.second["type"].as<std::string>(), "arrow");
        EXPECT_EQ(kv.second["arrowScale"].size(), 3u);
    }
}
