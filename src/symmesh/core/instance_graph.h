/// The instance graph of a templated structure (Section 4.2, Figure 4.6) —
/// spec/definitions.md#instance-graph
///
/// An undirected multigraph: one vertex per template; one edge per pair of distinct neighbouring
/// instances, labelled with its two transformations; and one self-loop per template for the
/// trivial interface interf(X, T_{i,g}, T_{i,g}), which makes the graph reflexive.
#pragma once
#include "symmesh/core/templated_structure.h"

#include <boost/graph/adjacency_list.hpp>

#include <string>

namespace symmesh::core {

struct TemplateNode {
  std::size_t template_index = 0;
  std::string name;
};

struct InterfaceEdge {
  InstanceId a, b;      ///< the two instances (a == b for the trivial self-loop)
  bool trivial = false; ///< the reflexive loop interf(X, T, T)
  std::string label() const { return trivial ? "I" : to_string(a) + " / " + to_string(b); }
};

using InstanceGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                            TemplateNode, InterfaceEdge>;

template <class FT, int D>
InstanceGraph instance_graph(const TemplatedStructure<FT, D>& x,
                             const StructureInstance<FT, D>& si) {
  InstanceGraph g(x.templates.size());
  for (std::size_t i = 0; i < x.templates.size(); ++i) {
    g[i].template_index = i;
    g[i].name = x.templates[i].name;
    boost::add_edge(i, i, InterfaceEdge{{i, 0}, {i, 0}, true}, g);
  }
  for (auto [a, b] : neighbouring_instances(si))
    boost::add_edge(si.ids[a].i, si.ids[b].i, InterfaceEdge{si.ids[a], si.ids[b], false}, g);
  return g;
}

} // namespace symmesh::core
