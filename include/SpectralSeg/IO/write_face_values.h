// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_face_values.h
/// \brief Writing one value per face of an input file, in that file's face order.
#ifndef SPECTRALSEG_IO_WRITE_FACE_VALUES_H
#define SPECTRALSEG_IO_WRITE_FACE_VALUES_H

#include <SpectralSeg/IO/Atomic_output_file.h>
#include <SpectralSeg/IO/Mesh_file_report.h>
#include <SpectralSeg/exceptions.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace IO {

/// \ingroup PkgSpectralSegIO
/// \brief Maps per-mesh-face values back to the faces of the file that
/// `report` describes. Faces the reader dropped as invalid get `missing`.
template <typename T>
std::vector<T> values_in_input_order(const Mesh_file_report& report, const std::vector<T>& per_mesh_face,
                                     const T& missing)
{
  std::vector<T> out(report.face_of_input_face.size(), missing);
  for(std::size_t p = 0; p < out.size(); ++p)
  {
    const std::size_t f = report.face_of_input_face[p];
    if(f != Mesh_file_report::no_face && f < per_mesh_face.size())
      out[p] = per_mesh_face[f];
  }
  return out;
}

/// \ingroup PkgSpectralSegIO
/// \brief Renumbers segment labels (one per mesh face) in the order in which
/// the faces of the file that `report` describes first show them: label 0
/// is the segment of the file's first face, label 1 the next segment met,
/// and so on; negative labels (no segment) stay.
///
/// The reader stores the faces along a Hilbert curve, not in the file's
/// order (`read_mesh_file()`), and the methods number segments in the
/// mesh's order; after this the numbers are those a reader in file order
/// would give, while the segments themselves do not depend on the order.
/// The tool and the Python module number their labels this way.
inline std::vector<int> number_segments_in_input_order(const Mesh_file_report& report,
                                                       const std::vector<int>& per_mesh_face)
{
  int count = 0;
  for(int l : per_mesh_face)
    count = std::max(count, l + 1);
  std::vector<int> number(std::size_t(count), -1);
  int next = 0;
  const auto meet = [&](std::size_t f) {
    if(f < per_mesh_face.size() && per_mesh_face[f] >= 0 && number[std::size_t(per_mesh_face[f])] < 0)
      number[std::size_t(per_mesh_face[f])] = next++;
  };
  for(const std::size_t f : report.face_of_input_face)
    if(f != Mesh_file_report::no_face)
      meet(f);
  for(std::size_t f = 0; f < per_mesh_face.size(); ++f) // faces no file face maps to, if any
    meet(f);
  std::vector<int> out(per_mesh_face.size());
  for(std::size_t f = 0; f < out.size(); ++f)
    out[f] = per_mesh_face[f] < 0 ? per_mesh_face[f] : number[std::size_t(per_mesh_face[f])];
  return out;
}

/// \ingroup PkgSpectralSegIO
/// \brief Writes one value per line: `inf` for an infinite value (an
/// unreachable face), `nan` for a face without value, full precision.
/// The file is written all or nothing (`Atomic_output_file`).
/// \throws Io_error if the file cannot be written; an existing file is then left unchanged
inline void write_face_values(const std::string& path, const std::vector<double>& values)
{
  Atomic_output_file file(path);
  std::ostream& out = file.stream();
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(double v : values)
  {
    if(std::isnan(v))
      out << "nan\n";
    else if(std::isinf(v))
      out << (v > 0 ? "inf\n" : "-inf\n");
    else
      out << v << '\n';
  }
  file.commit();
}

/// \ingroup PkgSpectralSegIO
/// \brief Writes one integer label per line, all or nothing (`Atomic_output_file`).
/// \throws Io_error if the file cannot be written; an existing file is then left unchanged
inline void write_face_values(const std::string& path, const std::vector<int>& labels)
{
  Atomic_output_file file(path);
  for(int v : labels)
    file.stream() << v << '\n';
  file.commit();
}

} // namespace IO
} // namespace SpectralSeg

#endif // SPECTRALSEG_IO_WRITE_FACE_VALUES_H
