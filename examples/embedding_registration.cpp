// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Registration by spectral embeddings (thesis 3.6): a mesh and a copy of it
// with one limb stretched are embedded spectrally under a metric, and the
// copy's embedding is aligned onto the original's by iterative closest
// points (Registration::align_embeddings()). The faces of the copy are the
// faces of the original, so we know where each should land. Per metric,
// relative to the embedding's size: how much the embedding changed (the
// residual of the best motion of each face onto its own counterpart), and
// after the closest-point alignment (no correspondence given) the
// closest-point distance and how far faces land from their own counterparts
// (large when a symmetric shape is matched mirrored). A metric that is
// blind to stretching changes the embedding less.
//
// usage: embedding_registration [mesh.off] [axis=0] [cut=0.45] [factor=1.6] [dimensions=3] [samples=24]
//   the copy: every vertex with coordinate `axis` above `cut` moves away
//   from the plane coordinate = cut by `factor` (data/human_man.off: the
//   right forearm and hand, 60% longer); the embeddings have `dimensions`
//   dimensions, from `samples` Nyström samples
#include <SpectralSeg/Registration/align_embeddings.h>
#include <SpectralSeg/k_way_segmentation.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <cmath>
#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace P = SpectralSeg::parameters;

int main(int argc, char** argv)
{
  const std::string path = argc > 1 ? argv[1] : SPECTRALSEG_DATA_DIR "/human_man.off";
  const int axis = argc > 2 ? std::stoi(argv[2]) : 0;
  const double cut = argc > 3 ? std::stod(argv[3]) : 0.45;
  const double factor = argc > 4 ? std::stod(argv[4]) : 1.6;
  const std::size_t dimensions = argc > 5 ? std::stoul(argv[5]) : 3;
  const std::size_t samples = argc > 6 ? std::stoul(argv[6]) : 24;
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(path, mesh) || !CGAL::is_triangle_mesh(mesh) || axis < 0 || axis > 2)
  {
    std::cerr << "cannot read a triangle mesh from " << path << std::endl;
    return 1;
  }
  Mesh stretched = mesh;
  std::size_t moved = 0;
  for(auto v : vertices(stretched))
  {
    const K::Point_3 p = stretched.point(v);
    if(p[axis] <= cut)
      continue;
    double c[3] = {p.x(), p.y(), p.z()};
    c[axis] = cut + factor * (c[axis] - cut);
    stretched.point(v) = K::Point_3(c[0], c[1], c[2]);
    ++moved;
  }
  std::cout << moved << " of " << num_vertices(mesh) << " vertices stretched by " << factor << "\n";

  auto compare = [&](const std::string& name, const auto& metric) {
    const auto np = P::metric(metric).number_of_nystrom_samples(samples).embedding_method(SpectralSeg::Embedding::Method::nystrom);
    const Eigen::MatrixXd a = SpectralSeg::spectral_embedding(mesh, dimensions, np).coordinates;
    const Eigen::MatrixXd b = SpectralSeg::spectral_embedding(stretched, dimensions, np).coordinates;
    if(a.cols() != b.cols())
    {
      std::cout << name << ": the embeddings have " << a.cols() << " and " << b.cols() << " dimensions\n";
      return;
    }
    const Eigen::RowVectorXd centre = a.colwise().mean();
    const double size = std::sqrt((a.rowwise() - centre).rowwise().squaredNorm().mean());
    // How much the embedding changed: the best motion of the copy's faces
    // onto their own counterparts (rows correspond), and what is left.
    SpectralSeg::Registration::Alignment_options known;
    known.rows_correspond = true;
    const double change = SpectralSeg::Registration::align_embeddings(b, a, known).rms_closest / size;
    // Registration proper: no correspondence, closest points; then how far
    // each aligned face lands from its own counterpart.
    const SpectralSeg::Registration::Embedding_alignment r = SpectralSeg::Registration::align_embeddings(b, a);
    const double error = std::sqrt((r.aligned - a).rowwise().squaredNorm().mean()) / size;
    std::cout << name << ": embedding change " << change << ", after closest-point alignment: closest-point distance "
              << r.rms_closest / size << ", face-to-own-face distance " << error << " (of the embedding's size)\n";
  };
  compare("geodesic", SpectralSeg::Metrics::Geodesic_weight());
  // the thesis's registration setting: alpha 0.1, beta 0, gamma 0.9
  compare("part-aware", SpectralSeg::Metrics::Part_aware_weight<>(0.1, 0., 0.9));
  return 0;
}
