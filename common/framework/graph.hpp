#pragma once
// The data-flow graph of a set of components: which member produces each topic, and a deterministic step order
// (topological over Lag::Same edges, ties broken by name). Used by the direct executor and the DDS hosts.
#include <map>
#include <string>
#include <vector>

#include "framework/compat.hpp"
#include "framework/component.hpp"

namespace gdnav::framework {

struct Graph {
    std::map<std::string, OutputBase*> producer;  // topic -> output port (within the given set)
    std::vector<Component*> order;                // step order
};

// Throws std::runtime_error on a topic with two producers or a zero-lag cycle.
Graph build_graph(const std::vector<Component*>& components);

// The topic graph as Graphviz DOT text (docs/architecture.md, "Topics"): one node per component, one edge per
// topic from its producer to each consumer, labelled with the topic's name; an input of the previous step
// (Lag::Previous, the feedback edges) is dashed and marked "k-1". Deterministic: nodes and edges sorted by name.
std::string graph_dot(const std::vector<Component*>& components, const std::string& title);

std::string join_topics(const std::vector<std::string>& topics);
std::vector<std::string> split_topics(const std::string& csv);
std::vector<std::string> input_topics(const Component& c);
std::vector<std::string> output_topics(const Component& c);

}  // namespace gdnav::framework
