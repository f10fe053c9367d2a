// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// Edge-collapse decimation for the benchmarks: the same shape with fewer
// faces (CGAL's Surface_mesh_simplification, Lindstrom-Turk cost and
// placement).
#ifndef SPECTRALSEG_BENCHMARK_DECIMATE_H
#define SPECTRALSEG_BENCHMARK_DECIMATE_H

#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <cstddef>

namespace spectralseg_bench {

// Collapses edges until the mesh has about `faces` faces (at most `faces` on
// a closed triangle mesh, where each collapse removes 3 edges and 2 faces).
// CGAL 5.5 only stops on an edge count, so the target edge count keeps the
// input's ratio of edges to faces. Leaves the mesh without removed elements.
template <typename Point>
void decimate(CGAL::Surface_mesh<Point>& m, std::size_t faces)
{
  const std::size_t f = num_faces(m), e = num_edges(m);
  if(faces >= f || f == 0)
    return;
  // stops as soon as fewer than `threshold` edges are left
  const std::size_t threshold = (e * faces) / f + 1;
  CGAL::Surface_mesh_simplification::Count_stop_predicate<CGAL::Surface_mesh<Point>> stop(threshold);
  CGAL::Surface_mesh_simplification::edge_collapse(m, stop);
  m.collect_garbage();
}

} // namespace spectralseg_bench

#endif
