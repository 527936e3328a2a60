// Copyright (c) 2026 The Discrete Lie Flow authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Must not compile: each wrongly bound use of Discrete_lie_flow_parameterizer_3
// below stops at one readable static_assert, and nothing else fails
// (test static_assert_messages, which lists the expected messages).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_lie_flow_parameterizer_3.h>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> SM;
typedef boost::graph_traits<SM>::vertex_descriptor vertex_descriptor;
typedef boost::graph_traits<SM>::halfedge_descriptor halfedge_descriptor;

// Neither a border parameterizer nor a Parameterizer_3 as the second argument.
std::size_t not_a_parameterizer() { return sizeof(SMP::Discrete_lie_flow_parameterizer_3<SM, int>); }

void wrong_maps(SM& sm, halfedge_descriptor bhd)
{
  auto points = sm.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  auto ints = sm.add_property_map<vertex_descriptor, int>("v:index").first;
  auto bools = sm.add_property_map<vertex_descriptor, bool>("v:parameterized").first;
  SMP::Discrete_lie_flow_parameterizer_3<SM> p;
  p.parameterize(sm, bhd, ints, ints, bools);   // a uv map of integers
  p.parameterize(sm, bhd, points, points, bools); // an index map of points
}

// CGAL's orbifold constructor.
void orbifold() { SMP::Discrete_lie_flow_parameterizer_3<SM> p(SMP::Triangle, SMP::Cotangent); }
