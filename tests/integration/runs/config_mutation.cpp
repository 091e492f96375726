#include "config_mutation.hpp"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "framework/topic_types.hpp"
#include "register_components.hpp"
#include "run_folders.hpp"

namespace fs = std::filesystem;

namespace gdnav::testing::fuzz {

namespace {

// Keys whose value is free text: any scalar is valid there.
bool free_text_key(const std::string& key) { return key == "description" || key == "name"; }

std::string path_str(const std::vector<Step>& p, std::size_t n) {
    std::string s;
    for (std::size_t i = 0; i < n; ++i) {
        if (const auto* k = std::get_if<std::string>(&p[i]))
            s += (s.empty() ? "" : ".") + *k;
        else
            s += "[" + std::to_string(std::get<std::size_t>(p[i])) + "]";
    }
    return s;
}

bool is_number(const YAML::Node& n) {
    const std::string& s = n.Scalar();
    if (s == "true" || s == "false" || s.empty()) return false;
    try {
        (void)n.as<double>();
        return true;
    } catch (const YAML::Exception&) {
        return false;
    }
}

void collect(const YAML::Node& n, std::vector<Step>& path, std::vector<Leaf>& out) {
    if (n.IsMap()) {
        for (const auto& kv : n) {
            path.emplace_back(kv.first.Scalar());
            collect(kv.second, path, out);
            path.pop_back();
        }
    } else if (n.IsSequence()) {
        for (std::size_t i = 0; i < n.size(); ++i) {
            path.emplace_back(i);
            collect(n[i], path, out);
            path.pop_back();
        }
    } else if (n.IsScalar()) {
        out.push_back({path, n.Scalar(), is_number(n)});
    }
}

// The node at path[0, n) (yaml-cpp nodes are handles: assigning through it changes the document).
YAML::Node at(YAML::Node root, const std::vector<Step>& p, std::size_t n) {
    YAML::Node cur = root;
    for (std::size_t i = 0; i < n; ++i) {
        if (const auto* k = std::get_if<std::string>(&p[i]))
            cur.reset(cur[*k]);
        else
            cur.reset(cur[std::get<std::size_t>(p[i])]);
    }
    return cur;
}

// Index of the last map key in the path: deleting a list element deletes the list, an unknown key goes next to it.
std::size_t last_key(const std::vector<Step>& p) {
    for (std::size_t i = p.size(); i-- > 0;)
        if (std::holds_alternative<std::string>(p[i])) return i;
    return 0;
}

std::string num_text(double v) {
    std::ostringstream os;
    os.precision(15);  // the file values have fewer digits: -0.27576, not -0.27576000000000001
    os << v;
    return os.str();
}

std::string emit(const YAML::Node& n) {
    YAML::Emitter em;
    em << n;
    return std::string(em.c_str()) + "\n";
}

Mutation garbage(const std::string& original, rnd::Stream& rs) {
    Mutation m;
    const int g = rs.uniform_int(0, 2);
    if (g == 0) {
        const int n = rs.uniform_int(1, 200);
        for (int i = 0; i < n; ++i) m.text.push_back(static_cast<char>(rs.uniform_int(0, 255)));
        m.detail = std::to_string(n) + " random bytes";
    } else if (g == 1) {
        const int cut = rs.uniform_int(1, static_cast<int>(original.size()) - 1);
        m.text = original.substr(0, static_cast<std::size_t>(cut)) + "\n]: {\n";
        m.detail = "first " + std::to_string(cut) + " bytes, then ']: {'";
    } else {
        m.text = "- just\n- a list\n";
        m.detail = "a list instead of a mapping";
    }
    return m;
}

}  // namespace

const char* kind_name(Kind k) {
    switch (k) {
        case Kind::kNan: return "nan";
        case Kind::kInf: return "inf";
        case Kind::kNegInf: return "-inf";
        case Kind::kNegative: return "negative";
        case Kind::kHuge: return "huge";
        case Kind::kText: return "text";
        case Kind::kList: return "list";
        case Kind::kDelete: return "delete";
        case Kind::kUnknownKey: return "unknown-key";
        case Kind::kGarbage: return "garbage";
    }
    return "?";
}

bool number_kind(Kind k) {
    return k == Kind::kNan || k == Kind::kInf || k == Kind::kNegInf || k == Kind::kNegative || k == Kind::kHuge;
}

std::vector<Leaf> collect_leaves(const YAML::Node& doc) {
    std::vector<Leaf> leaves;
    std::vector<Step> path;
    collect(doc, path, leaves);
    return leaves;
}

Mutation mutate(const YAML::Node& doc, const std::string& original, const Leaf& leaf, Kind kind, rnd::Stream& rs) {
    if (kind == Kind::kGarbage) return garbage(original, rs);
    const std::size_t lk = last_key(leaf.path);
    const std::string leaf_key = std::get<std::string>(leaf.path[lk]);
    Mutation m;
    m.key = path_str(leaf.path, lk + 1);
    YAML::Node root = YAML::Clone(doc);
    YAML::Node node = at(root, leaf.path, leaf.path.size());
    const double v = leaf.numeric ? node.as<double>() : 0.0;
    switch (kind) {
        case Kind::kNan: node = ".nan"; break;
        case Kind::kInf: node = ".inf"; break;
        case Kind::kNegInf: node = "-.inf"; break;
        case Kind::kNegative: node = num_text(v > 0 ? -v : v < 0 ? v * 1e6 : -1.0); break;
        case Kind::kHuge: node = "1.0e+300"; break;
        case Kind::kText: node = "fuzz text"; break;
        case Kind::kList: {
            YAML::Node l(YAML::NodeType::Sequence);
            l.push_back(1);
            l.push_back("two");
            node = l;
            break;
        }
        case Kind::kDelete: at(root, leaf.path, lk).remove(leaf_key); break;
        case Kind::kUnknownKey: {
            at(root, leaf.path, lk)["fuzz_unknown_key"] = 1;
            m.key = path_str(leaf.path, lk);
            m.key += (m.key.empty() ? "" : ".") + std::string("fuzz_unknown_key");
            break;
        }
        case Kind::kGarbage: break;
    }
    if (kind != Kind::kDelete && kind != Kind::kUnknownKey)
        m.detail = path_str(leaf.path, leaf.path.size()) + ": " + leaf.value + " -> " +
                   (kind == Kind::kList ? "[1, two]" : node.Scalar());
    else
        m.detail = kind == Kind::kDelete ? m.key + " removed" : m.key + " added";
    // A non-number replacing a string leaf is judged like text.
    m.may_accept = (leaf.numeric && (kind == Kind::kNegative || kind == Kind::kHuge)) || kind == Kind::kDelete ||
                   (!leaf.numeric && (number_kind(kind) || kind == Kind::kText) && free_text_key(leaf_key));
    m.text = emit(root);
    return m;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

void write_text(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }

void write_derived_scenario(const fs::path& cfg, const std::string& name,
                            const std::vector<std::tuple<std::string, std::string, std::string>>& sets) {
    YAML::Node doc = YAML::Load(read_text(cfg / "scenarios" / "paper2.yaml"));
    for (const auto& [comp, key, value] : sets) doc["components"][comp][key] = value;
    write_text(cfg / "scenarios" / (name + ".yaml"), emit(doc));
}

fs::path private_config(const std::string& tag, framework::ComponentRegistry& reg) {
    const fs::path tmp = temp_dir(tag);
    fs::copy(fs::path(GDNAV_SOURCE_DIR) / "config", tmp / "config", fs::copy_options::recursive);
    ::setenv("GDNAV_CONFIG_DIR", (tmp / "config").c_str(), 1);
    framework::register_gdnav_topics();
    cli::register_all_components(reg);
    return tmp;
}

}  // namespace gdnav::testing::fuzz
