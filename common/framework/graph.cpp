#include "framework/graph.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

namespace gdnav::framework {

Graph build_graph(const std::vector<Component*>& components) {
    Graph g;
    for (Component* c : components)
        for (OutputBase* o : c->outputs()) {
            if (g.producer.count(o->topic()))
                throw std::runtime_error("topic '" + o->topic() + "' has two producers");
            g.producer[o->topic()] = o;
        }
    std::map<std::string, Component*> owner;
    for (Component* c : components)
        for (OutputBase* o : c->outputs()) owner[o->topic()] = c;

    // Kahn's algorithm; the ready set is ordered by name so the order never depends on input order.
    std::map<Component*, std::set<Component*>> deps;
    for (Component* c : components) {
        deps[c];
        for (InputBase* in : c->inputs()) {
            if (in->lag() != Lag::Same) continue;
            auto it = owner.find(in->topic());
            if (it != owner.end() && it->second != c) deps[c].insert(it->second);
        }
    }
    auto by_name = [](Component* a, Component* b) { return a->name() < b->name(); };
    std::set<Component*, decltype(by_name)> ready(by_name);
    for (auto& [c, d] : deps)
        if (d.empty()) ready.insert(c);
    while (!ready.empty()) {
        Component* c = *ready.begin();
        ready.erase(ready.begin());
        g.order.push_back(c);
        for (auto& [other, d] : deps)
            if (d.erase(c) && d.empty()) ready.insert(other);
    }
    if (g.order.size() != components.size()) {
        std::string cyc;
        for (auto& [c, d] : deps)
            if (!d.empty()) cyc += (cyc.empty() ? "" : ", ") + c->name();
        throw std::runtime_error("zero-lag cycle between components: " + cyc +
                                 " (one edge of every feedback loop must be Lag::Previous)");
    }
    return g;
}

std::string graph_dot(const std::vector<Component*>& components, const std::string& title) {
    std::map<std::string, std::string> owner;  // topic -> producing component
    for (const Component* c : components)
        for (const OutputBase* o : c->outputs()) owner[o->topic()] = c->name();
    std::set<std::string> nodes, edges;
    for (const Component* c : components) {
        nodes.insert("  \"" + c->name() + "\";\n");
        for (const InputBase* in : c->inputs()) {
            const auto it = owner.find(in->topic());
            if (it == owner.end()) continue;  // produced outside this set (an external member)
            std::string topic = in->topic();
            if (topic.rfind("gdnav/", 0) == 0) topic = topic.substr(6);
            const bool previous = in->lag() == Lag::Previous;
            edges.insert("  \"" + it->second + "\" -> \"" + c->name() + "\" [label=\"" + topic +
                         (previous ? " (k-1)\", style=dashed" : "\"") + "];\n");
        }
    }
    std::string dot = "digraph gdnav_topics {\n  label=\"" + title +
                      "\";\n  labelloc=t;\n  rankdir=LR;\n  node [shape=box, fontname=Helvetica];\n"
                      "  edge [fontname=Helvetica, fontsize=9];\n";
    for (const auto& n : nodes) dot += n;
    for (const auto& e : edges) dot += e;
    return dot + "}\n";
}

std::string join_topics(const std::vector<std::string>& topics) {
    std::string s;
    for (const auto& t : topics) s += (s.empty() ? "" : ",") + t;
    return s;
}

std::vector<std::string> split_topics(const std::string& csv) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start < csv.size()) {
        const std::size_t end = csv.find(',', start);
        const std::string t = csv.substr(start, end == std::string::npos ? std::string::npos : end - start);
        if (!t.empty()) out.push_back(t);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return out;
}

std::vector<std::string> input_topics(const Component& c) {
    std::vector<std::string> v;
    for (auto* i : c.inputs()) v.push_back(i->topic());
    return v;
}

std::vector<std::string> output_topics(const Component& c) {
    std::vector<std::string> v;
    for (auto* o : c.outputs()) v.push_back(o->topic());
    return v;
}

}  // namespace gdnav::framework
