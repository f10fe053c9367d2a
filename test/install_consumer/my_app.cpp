// my_app MESH K OUT: segments a triangle mesh into K parts and writes it in the
// colours of its segments (OUT: .ply with the labels, .obj + .mtl, or .off).
#include <SpectralSeg/IO/write_segmented_mesh.h>
#include <SpectralSeg/k_way_segmentation.h>
#include <SpectralSeg/version.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <iostream>
#include <string>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Face_index face_descriptor;

int main(int argc, char** argv)
{
  Mesh mesh;
  if(argc != 4 || !CGAL::IO::read_polygon_mesh(argv[1], mesh))
  {
    std::cerr << "usage: my_app MESH K OUT.ply (MESH: a triangle mesh, .off .obj .ply .stl)\n";
    return 1;
  }
  try
  {
    auto segment = mesh.add_property_map<face_descriptor, std::size_t>("f:segment").first;
    std::size_t n = SpectralSeg::k_way_segmentation(mesh, std::stoul(argv[2]), segment,
                                                    SpectralSeg::parameters::number_of_threads(0));
    SpectralSeg::IO::write_segmented_mesh(argv[3], mesh, segment);
    std::cout << "SpectralSeg " << SPECTRALSEG_VERSION_STRING << ": " << n << " segments in " << argv[3] << "\n";
  }
  catch(const SpectralSeg::Error& e) // bad input, a file that cannot be written, ...
  {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
