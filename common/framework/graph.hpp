#pragma once
// The data-flow graph of a set of components: which member produces each topic, and a deterministic step order
// (topological over Lag::Same edges, ties broken by name). Used by the direct executor and the DDS hosts.
#include <map>
#include <string>
#include <vector>

#include "framework/component.hpp"

namespace gdnav::runtime {

struct Graph {
    std::map<std::string, OutputBase*> producer;  // topic -> output port (within the given set)
    std::vector<Component*> order;                // step order
};

// Throws std::runtime_error on a topic with two producers or a zero-lag cycle.
Graph build_graph(const std::vector<Component*>& components);

std::string join_topics(const std::vector<std::string>& topics);
std::vector<std::string> split_topics(const std::string& csv);
std::vector<std::string> input_topics(const Component& c);
std::vector<std::string> output_topics(const Component& c);

}  // namespace gdnav::runtime
