// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Segments a CGAL::Surface_mesh into k parts with the part-aware metric,
// prints the area of each segment, and writes the mesh in the colours of its
// segments (a PLY file that Blender, MeshLab and Open3D show in colour, with
// the labels as a face property). Then asks for the spectral embedding alone, as a user who runs
// their own clustering would, and scores the two results against each
// other with the Rand index. Last, on a weighted dual graph built once: the
// thesis's method against the default (which over-segments and merges), a
// merge done by hand, and the automatic choice of k.
//
// usage: k_way_segmentation [mesh.off] [k=6] [out.ply]
#include <SpectralSeg/Clustering/Kmeans.h>
#include <SpectralSeg/IO/write_segmented_mesh.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Refinement/crease_regions.h>
#include <SpectralSeg/Refinement/merge_segments.h>
#include <SpectralSeg/Refinement/sharp_crease_share.h>
#include <SpectralSeg/evaluation.h>
#include <SpectralSeg/k_way_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : SPECTRALSEG_DATA_DIR "/elephant.off";
  const std::size_t k = argc > 2 ? std::stoul(argv[2]) : 6;
  const std::string out = argc > 3 ? argv[3] : "k_way_segmentation.ply";
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "cannot read a triangle mesh from " << path << std::endl;
    return 1;
  }
  namespace P = SpectralSeg::parameters;

  // One call: part-aware metric, Nyström embedding, K-means, graph cut.
  auto segment = mesh.add_property_map<face_descriptor, std::size_t>("f:segment").first;
  const std::size_t count = SpectralSeg::k_way_segmentation(mesh, k, segment, P::number_of_threads(0));

  std::vector<double> area(count, 0.);
  for(face_descriptor f : faces(mesh))
    area[get(segment, f)] += CGAL::to_double(CGAL::Polygon_mesh_processing::face_area(f, mesh));
  std::cout << count << " segments; areas:";
  for(double a : area)
    std::cout << ' ' << a;
  std::cout << "\n";

  SpectralSeg::IO::write_segmented_mesh(out, mesh, segment); // .ply, .obj (+ .mtl) or .off
  std::cout << "coloured mesh: " << out << "\n";
  std::vector<int> labels;
  for(face_descriptor f : faces(mesh))
    labels.push_back(static_cast<int>(get(segment, f)));

  // The embedding alone (rows follow the face index), clustered by hand.
  const SpectralSeg::Embedding::Spectral_embedding embedding = SpectralSeg::spectral_embedding(mesh, k);
  const SpectralSeg::Clustering::Kmeans_result clusters = SpectralSeg::Clustering::kmeans(embedding.coordinates, k);
  std::cout << "embedding: " << embedding.coordinates.rows() << " x " << embedding.coordinates.cols()
            << (embedding.exact ? " (exact)" : " (Nystrom)") << "; plain K-means vs k_way_segmentation, Rand index error "
            << SpectralSeg::Evaluation::rand_index_error(clusters.labels, labels) << std::endl;

  // The metric once, then several segmentations of the same weighted graph.
  const SpectralSeg::Dual_graph graph = SpectralSeg::make_dual_graph(mesh);
  const SpectralSeg::Weighted_dual_graph weighted(
    graph, SpectralSeg::Metrics::metric_values(SpectralSeg::Metrics::Part_aware_weight<>(), graph));
  const SpectralSeg::K_way_result ours = SpectralSeg::segment_k_way(weighted, k);
  const SpectralSeg::K_way_result thesis =
    SpectralSeg::segment_k_way(weighted, k, SpectralSeg::K_way_options::thesis());
  std::cout << "default (k + " << ours.extra_clusters << " clusters merged back to k"
            << (ours.contrast_merge ? " by contrast" : "") << ", kept of k + "
            << SpectralSeg::K_way_options().extra_clusters << ", k + "
            << SpectralSeg::K_way_options().alternative_extra_clusters.at(0) << " and "
            << SpectralSeg::K_way_options().contrast_merge_clusters << " merged by contrast): "
            << ours.number_of_segments << " segments; thesis's method: " << thesis.number_of_segments
            << " segments; Rand index error between them "
            << SpectralSeg::Evaluation::rand_index_error(ours.labels, thesis.labels) << "\n";

  // One over-segmentation only (k + 2 clusters): faster, but the default's
  // choice among three, the one whose boundaries follow concave creases
  // best, gives better parts on psb-dev.
  SpectralSeg::K_way_options single;
  single.alternative_extra_clusters.clear();
  single.contrast_merge_clusters = 0;
  const SpectralSeg::K_way_result one = SpectralSeg::segment_k_way(weighted, k, single);
  std::cout << "one over-segmentation: concave normalized cut "
            << SpectralSeg::Refinement::concave_normalized_cut(graph, one.labels, single.cut_angle_scale)
            << " (default's: " << ours.normalized_cut << ")\n";

  // Merging by hand: the thesis's segments, merged down to 3 across the
  // least concave boundaries.
  std::vector<int> merged = thesis.labels;
  const std::size_t left = SpectralSeg::Refinement::merge_weakest_boundaries(
    graph, SpectralSeg::Refinement::concave_angle_weights(graph), merged, 3);
  std::cout << "thesis's segments merged by hand: " << left << " segments\n";

  // The same angles as measured on a tessellation of at most a quarter of
  // the faces: a finer mesh's normals are averaged first, so that a sharp
  // crease and a smooth fold compare as on the coarser mesh (what the
  // contrast merge does above 50,000 faces).
  std::vector<int> coarse = thesis.labels;
  SpectralSeg::Refinement::merge_weakest_boundaries(
    graph, SpectralSeg::Refinement::concave_angle_weights(graph, graph.number_of_faces() / 4), coarse, 3);
  std::cout << "merged with the angles at a quarter of the resolution, Rand index error to the above "
            << SpectralSeg::Evaluation::rand_index_error(merged, coarse) << "\n";

  // The same with the embedding-separation factor: pieces that overlap in
  // the thesis's spectral embedding go first. segment_k_way() uses it on
  // meshes whose folds are mostly blunt (a small sharp crease share).
  SpectralSeg::Refinement::Embedding_separation separation;
  separation.coordinates = &thesis.embedding.coordinates;
  std::vector<int> separated = thesis.labels;
  SpectralSeg::Refinement::merge_weakest_boundaries(graph, SpectralSeg::Refinement::concave_angle_weights(graph),
                                                    separated, 3, std::numeric_limits<double>::infinity(), 0., 0.,
                                                    separation);
  std::cout << "sharp crease share " << SpectralSeg::Refinement::sharp_crease_share(graph)
            << "; merged with the separation factor, Rand index error to the above "
            << SpectralSeg::Evaluation::rand_index_error(merged, separated) << "\n";

  // The regions that closed loops of concave creases (45 degrees or more)
  // enclose, and the thesis's segments cut along them: what segment_k_way()
  // does to its clusters before merging.
  std::vector<int> region;
  const std::size_t regions = SpectralSeg::Refinement::crease_regions(graph, 45., region);
  std::vector<int> cut = thesis.labels;
  std::cout << "crease regions: " << regions << "; thesis's segments cut along them: "
            << SpectralSeg::Refinement::split_along_regions(region, cut) << " labels\n";

  // k chosen by the library, at most 12.
  SpectralSeg::K_way_automatic_options automatic_options;
  automatic_options.max_k = 12;
  const SpectralSeg::K_way_result automatic = SpectralSeg::segment_k_way_automatic(weighted, automatic_options);
  std::cout << "automatic: " << automatic.number_of_segments << " segments" << std::endl;

  // The part-aware metric also measured the shape's thickness at each face
  // (Metrics::vsi_face_thickness()): the contrast merge of segment_hybrid()
  // keeps a boundary between a thin segment and a thick one. A face where
  // no ray was measured (open meshes) has NaN.
  std::vector<double> thickness;
  for(double t : weighted.face_thickness())
    if(!std::isnan(t))
      thickness.push_back(t);
  if(!thickness.empty())
  {
    std::nth_element(thickness.begin(), thickness.begin() + std::ptrdiff_t(thickness.size() / 2), thickness.end());
    std::cout << "median thickness of the shape at a face: " << thickness[thickness.size() / 2] << std::endl;
  }
  return 0;
}
