// Issue 16 item 1: a gdnav recording is a standard MCAP file. A scenario-#2 run recorded with every data topic is
// read by the official TypeScript reader (@mcap/core, indexed and streaming, zstd through @foxglove/wasm-zstd) and
// every message of every channel is decoded by Foxglove's OMG IDL deserializer from the schema in the file
// (mcap_node/check_mcap.mjs). The values must equal gdnav's own reader's: every field (field tables of the IDL) of
// every topic at several steps, message counts, metadata and the run.yaml attachment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "h5_column.hpp"
#include "process_util.hpp"
#include "io/recording/record_file.hpp"
#include "framework/fields/field_table.hpp"
#include "framework/topic_types.hpp"

using namespace gdnav::testing;
namespace fs = std::filesystem;
namespace fields = gdnav::framework::fields;

namespace {

std::string json_string(const std::string& s) {
    std::string o = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') o += '\\';
        o += c;
    }
    return o + "\"";
}

// Every field of one decoded sample: "name": {"kind": K, "values": ["..", ...]} (values as exact strings).
std::string sample_json(const fields::TypeFields& table, void* sample) {
    std::ostringstream o;
    o << "{";
    for (std::size_t i = 0; i < table.count; ++i) {
        const fields::Field& f = table.fields[i];
        o << (i ? ", " : "") << json_string(f.name) << ": {\"kind\": ";
        std::vector<std::string> v;
        char buf[40];
        switch (f.kind) {
            case fields::Kind::F64:
                o << "\"f64\"";
                for (std::size_t k = 0; k < f.count; ++k) {
                    std::snprintf(buf, sizeof(buf), "%.17g", static_cast<double*>(f.ptr(sample))[k]);
                    v.push_back(buf);
                }
                break;
            case fields::Kind::U64:
                o << "\"u64\"";
                for (std::size_t k = 0; k < f.count; ++k)
                    v.push_back(std::to_string(static_cast<std::uint64_t*>(f.ptr(sample))[k]));
                break;
            case fields::Kind::U32:
                o << "\"u32\"";
                for (std::size_t k = 0; k < f.count; ++k)
                    v.push_back(std::to_string(static_cast<std::uint32_t*>(f.ptr(sample))[k]));
                break;
            case fields::Kind::U8:
                o << "\"u8\"";
                for (std::size_t k = 0; k < f.count; ++k)
                    v.push_back(std::to_string(static_cast<std::uint8_t*>(f.ptr(sample))[k]));
                break;
            case fields::Kind::Bool:
                o << "\"bool\"";
                for (std::size_t k = 0; k < f.count; ++k) v.push_back(static_cast<bool*>(f.ptr(sample))[k] ? "true" : "false");
                break;
            case fields::Kind::Enum:
                o << "\"enum\"";
                v.push_back(std::to_string(*static_cast<std::uint32_t*>(f.ptr(sample))));
                break;
            case fields::Kind::String:
                o << "\"string\"";
                v.push_back(f.get_str(sample));
                break;
        }
        o << ", \"values\": [";
        for (std::size_t k = 0; k < v.size(); ++k) o << (k ? ", " : "") << json_string(v[k]);
        o << "]}";
    }
    return o.str() + "}";
}

// The run's run.h5 (nav_recorder: a row every 10 steps; /gnss at the fix epochs) as expected values of the topic
// fields it copies unchanged: {"TOPIC": {"STEP": {"field": {"kind", "values"}}}} at the rows of the given steps.
// (Only these topics have their fields in run.h5; the sensors', guidance's and control's are in the MCAP only.)
struct H5Field {
    const char* topic;
    const char* table;
    const char* field;                 // dotted name in the message
    std::vector<const char*> columns;  // one per value (an array field: one per element)
    bool boolean = false;
};

std::string h5_expected(const fs::path& h5, double t0_s, double dt_s, const std::vector<std::uint64_t>& steps,
                        std::size_t& values) {
    const std::vector<H5Field> map{
        {"gdnav/Truth", "truth", "lat_rad", {"lat_rad"}},
        {"gdnav/Truth", "truth", "lon_rad", {"lon_rad"}},
        {"gdnav/Truth", "truth", "h_m", {"h_m"}},
        {"gdnav/Truth", "truth", "v_n_mps", {"vn_mps", "ve_mps", "vd_mps"}},
        {"gdnav/Truth", "truth", "euler_rad", {"yaw_rad", "pitch_rad", "bank_rad"}},
        {"gdnav/Truth", "truth", "tas_mps", {"tas_mps"}},
        {"gdnav/Truth", "truth", "aoa_rad", {"aoa_rad"}},
        {"gdnav/Truth", "truth", "dp_Pa", {"dp_Pa"}},
        {"gdnav/Truth", "truth", "wind_n_mps", {"wind_n_mps", "wind_e_mps", "wind_d_mps"}},
        {"gdnav/PositionEstimate", "estimate", "lat_rad", {"lat_rad"}},
        {"gdnav/PositionEstimate", "estimate", "lon_rad", {"lon_rad"}},
        {"gdnav/PositionEstimate", "estimate", "h_m", {"h_m"}},
        {"gdnav/PositionEstimate", "estimate", "v_n_mps", {"vn_mps", "ve_mps", "vd_mps"}},
        {"gdnav/PositionEstimate", "estimate", "gnss_denied", {"gnss_denied"}, true},
        {"gdnav/AirDataEstimate", "estimate", "tas_mps", {"tas_mps"}},
        {"gdnav/AirDataEstimate", "estimate", "Hp_m", {"Hp_m"}},
        {"gdnav/AirDataEstimate", "estimate", "T_K", {"T_K"}},
        {"gdnav/GnssSample", "gnss", "lat_rad", {"lat_rad"}},
        {"gdnav/GnssSample", "gnss", "v_n_mps", {"vn_mps", "ve_mps", "vd_mps"}},
    };
    // topic -> step -> field -> (kind, values)
    std::map<std::string, std::map<std::uint64_t, std::map<std::string, std::pair<std::string, std::vector<std::string>>>>> want;
    for (const auto& m : map) {
        const std::vector<double> t = h5_column(h5, m.table, "t_s");
        for (std::size_t c = 0; c < m.columns.size(); ++c) {
            const std::vector<double> col = h5_column(h5, m.table, m.columns[c]);
            if (t.empty() || col.size() != t.size()) {
                ADD_FAILURE() << "run.h5 /" << m.table << " has no column " << m.columns[c];
                continue;
            }
            for (std::size_t i = 0; i < t.size(); ++i) {
                const auto step = static_cast<std::uint64_t>(std::llround((t[i] - t0_s) / dt_s));
                // /gnss has rows at the fix epochs only: the first fix at or after each listed step.
                const bool at = m.table == std::string("gnss")
                                    ? std::any_of(steps.begin(), steps.end(),
                                                  [&](std::uint64_t s) { return step >= s && step < s + 100; })
                                    : std::find(steps.begin(), steps.end(), step) != steps.end();
                if (!at) continue;
                char buf[40];
                std::snprintf(buf, sizeof(buf), "%.17g", col[i]);
                auto& [kind, v] = want[m.topic][step][m.field];
                kind = m.boolean ? "bool" : "f64";
                v.push_back(m.boolean ? (col[i] != 0.0 ? "true" : "false") : buf);
                ++values;
            }
        }
    }
    std::ostringstream o;
    o << "{";
    bool first_topic = true;
    for (const auto& [topic, by_step] : want) {
        o << (first_topic ? "" : ", ") << json_string(topic) << ": {";
        first_topic = false;
        bool first_step = true;
        for (const auto& [step, fields] : by_step) {
            o << (first_step ? "" : ", ") << "\"" << step << "\": {";
            first_step = false;
            bool first_field = true;
            for (const auto& [name, kv] : fields) {
                o << (first_field ? "" : ", ") << json_string(name) << ": {\"kind\": \"" << kv.first
                  << "\", \"values\": [";
                for (std::size_t k = 0; k < kv.second.size(); ++k) o << (k ? ", " : "") << json_string(kv.second[k]);
                o << "]}";
                first_field = false;
            }
            o << "}";
        }
        o << "}";
    }
    return o.str() + "}";
}

}  // namespace

TEST(McapNode, OfficialReaderDecodesEveryMessageLikeGdnavsReader) {
    gdnav::framework::register_gdnav_topics();
    const fs::path out = temp_dir("mcap-node");
    // Scenario #2, seed 1, 3001 steps (t = -50 .. -20 s), every data topic (1 MiB chunks: 4 of them).
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", "3001", "--layout",
                          "direct", "--record", "all", "--out", out.string()},
                         120.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;

    // Expected values from gdnav's own reader: every field at steps 0, 1, 997, 1500 and the last.
    const gdnav::io::recording::Recording rec = gdnav::io::recording::read_recording(out / "record");
    ASSERT_TRUE(rec.complete) << rec.problem;
    ASSERT_EQ(rec.topics.size(), gdnav::framework::known_topics().size());
    std::ostringstream json;
    json << "{\"topics\": {";
    bool first_topic = true;
    for (const auto& [topic, tr] : rec.topics) {
        ASSERT_EQ(tr.entries.size(), 3001u) << topic;
        const fields::TypeFields* table = fields::find_type_fields(tr.ops->type_name);
        ASSERT_NE(table, nullptr) << tr.ops->type_name;
        gdnav::io::recording::SampleDecoder dec(*tr.ops);
        std::unique_ptr<void, void (*)(void*)> s(tr.ops->create(), tr.ops->destroy);
        json << (first_topic ? "" : ", ") << json_string(topic) << ": {\"type\": " << json_string(tr.ops->type_name)
             << ", \"count\": " << tr.entries.size() << ", \"samples\": {";
        first_topic = false;
        bool first = true;
        for (std::size_t i : {std::size_t{0}, std::size_t{1}, std::size_t{997}, std::size_t{1500}, tr.entries.size() - 1}) {
            const auto& e = tr.entries[i];
            ASSERT_TRUE(dec.decode(&tr.bytes[e.offset], e.size, s.get()));
            json << (first ? "" : ", ") << "\"" << e.step << "\": " << sample_json(*table, s.get());
            first = false;
        }
        json << "}}";
    }
    // And the fields that run.h5 holds, at its rows of steps 0, 1000, 2000 and 3000 (and the GNSS fixes after them).
    std::size_t h5_values = 0;
    json << "}, \"h5\": " << h5_expected(out / "run.h5", -50.0, 0.01, {0, 1000, 2000, 3000}, h5_values);
    EXPECT_GT(h5_values, 100u);
    json << ", \"metadata\": {\"seed\": \"1\", \"run_index\": \"0\", \"steps\": \"3001\", \"t0_s\": \""
         << rec.run_metadata.at("t0_s") << "\", \"config_digest\": \"" << rec.run_metadata.at("config_digest")
         << "\"}, \"run_yaml_bytes\": " << rec.run_yaml.size() << "}\n";
    EXPECT_EQ(rec.run_metadata.at("t0_s"), "-50");
    EXPECT_EQ(rec.run_yaml, read_file(out / "run.yaml"));
    const fs::path expected = out / "expected.json";
    std::ofstream(expected) << json.str();

    const std::string script = std::string(GDNAV_MCAP_NODE_DIR) + "/check_mcap.mjs";
    const Result node = run({GDNAV_NODE, script, (out / "record" / "run.mcap").string(), expected.string()}, 120.0);
    std::printf("%s", node.output.c_str());
    EXPECT_EQ(node.exit_code, 0) << node.output;
    EXPECT_NE(node.output.find("PASS"), std::string::npos);
    if (!::testing::Test::HasFailure()) fs::remove_all(out);
}

// The viewer channels (--record ...,viewer; common/io/viewer) of a scenario-#2 run that crosses the
// GNSS loss (t = 100 s) are decoded by Foxglove's deserializer from the schemas in the file and compared, in
// mcap_node/check_viewer.mjs, with the raw topics of the same file and with the run's run.h5 /error rows (the
// nav_recorder's errors, written here as EXPECTED.json). gdnav's own reader skips the viewer channels.
TEST(McapNode, ViewerChannelsDecodeAndMatchTruthEstimatesAndRunH5) {
    gdnav::framework::register_gdnav_topics();
    const fs::path out = temp_dir("mcap-viewer");
    constexpr std::uint64_t kSteps = 16001;  // t = -50 .. 110 s
    const Result r = run({GDNAV_GDNAV_EXE, "run", "--scenario", "paper2", "--seed", "1", "--steps", std::to_string(kSteps),
                          "--layout", "direct", "--record", "Truth,AttitudeEstimate,PositionEstimate,viewer", "--out",
                          out.string()},
                         240.0);
    ASSERT_EQ(r.exit_code, 0) << r.output;

    const gdnav::io::recording::Recording rec = gdnav::io::recording::read_recording(out / "record");
    ASSERT_TRUE(rec.complete) << rec.problem;
    EXPECT_EQ(rec.topics.size(), 3u);
    EXPECT_EQ(rec.derived_channels.size(), 7u);
    const double t0 = std::stod(rec.run_metadata.at("t0_s"));
    const double dt = std::stod(rec.run_metadata.at("dt_s"));

    // run.h5 /error, keyed by step (rows every `decimation` steps of the nav_recorder, 10 by default as the viewer's).
    const fs::path h5 = out / "run.h5";
    const std::vector<double> t_s = h5_column(h5, "error", "t_s");
    ASSERT_GT(t_s.size(), 1000u);
    const char* cols[] = {"rot_rad", "yaw_rad", "pitch_rad", "bank_rad", "hor_m", "cross_m",
                          "along_m", "h_m",     "vn_mps",    "ve_mps",   "tas_mps"};
    std::vector<std::vector<double>> values;
    for (const char* c : cols) {
        values.push_back(h5_column(h5, "error", c));
        ASSERT_EQ(values.back().size(), t_s.size()) << c;
    }
    std::ostringstream json;
    char buf[64];
    json << "{\"step_ns\": " << rec.run_metadata.at("step_ns") << ", \"decimation\": 10, \"steps\": " << kSteps
         << ", \"t0_s\": " << rec.run_metadata.at("t0_s") << ", \"dt_s\": " << rec.run_metadata.at("dt_s")
         << ", \"errors\": {";
    for (std::size_t i = 0; i < t_s.size(); ++i) {
        const long long k = std::llround((t_s[i] - t0) / dt);
        ASSERT_EQ(k % 10, 0) << "run.h5 row " << i;
        json << (i ? ", " : "") << "\"" << k << "\": {";
        for (std::size_t c = 0; c < values.size(); ++c) {
            std::snprintf(buf, sizeof(buf), "%.17g", values[c][i]);
            json << (c ? ", " : "") << "\"" << cols[c] << "\": " << buf;
        }
        json << "}";
    }
    json << "}}\n";
    const fs::path expected = out / "expected_viewer.json";
    std::ofstream(expected) << json.str();

    const std::string script = std::string(GDNAV_MCAP_NODE_DIR) + "/check_viewer.mjs";
    const Result node = run({GDNAV_NODE, script, (out / "record" / "run.mcap").string(), expected.string()}, 120.0);
    std::printf("%s", node.output.c_str());
    EXPECT_EQ(node.exit_code, 0) << node.output;
    EXPECT_NE(node.output.find("PASS"), std::string::npos);
    if (!::testing::Test::HasFailure()) fs::remove_all(out);
}
