// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file label_files.h
/// \brief Reading and writing per-face label files (the Princeton
/// Segmentation Benchmark's `.seg` format: one integer per face).
#ifndef SPECTRALSEG_EVALUATION_LABEL_FILES_H
#define SPECTRALSEG_EVALUATION_LABEL_FILES_H

#include <SpectralSeg/IO/internal/Polygon_soup.h>
#include <SpectralSeg/IO/internal/Text_cursor.h>
#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/exceptions.h>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace SpectralSeg {
namespace Evaluation {

/// \cond SKIP_IN_MANUAL
namespace internal {

// The labels of the bytes of a label file (what `read_labels()` and the
// label fuzz target call).
inline std::vector<int> parse_labels(const IO::internal::File_bytes& file)
{
  IO::internal::Text_cursor in(file, 0);
  std::vector<int> labels;
  std::string_view token;
  while(in.next(token))
  {
    std::int64_t v = 0;
    if(IO::internal::parse_signed(token, v) != IO::internal::Parse_status::ok ||
       v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      throw Io_error("label file '" + file.path + "'" + in.where() + ": " + IO::internal::quoted(token) +
                     " is not an integer label");
    labels.push_back(static_cast<int>(v));
  }
  if(labels.empty())
    throw Io_error("label file '" + file.path + "' holds no label");
  return labels;
}

} // namespace internal
/// \endcond

/// \ingroup PkgSpectralSegEvaluation
/// \brief Reads a label file: whitespace-separated integers (the benchmark's
/// `.seg` files have one per line), one per face in the file's face order.
/// \throws Io_error if the file cannot be opened or read, is not a regular
///         file (a directory, a device, a FIFO), holds a token that is not
///         an integer in the range of `int`, or holds no label; the message
///         names the file (and the line of a bad token)
inline std::vector<int> read_labels(const std::string& path)
{
  return internal::parse_labels(IO::internal::read_file_bytes(path, "label file"));
}

/// \ingroup PkgSpectralSegEvaluation
/// \brief Writes one integer label per line, the format `read_labels()` reads.
/// \throws Io_error if the file cannot be written
inline void write_labels(const std::string& path, const std::vector<int>& labels)
{
  IO::write_face_values(path, labels);
}

} // namespace Evaluation
} // namespace SpectralSeg

#endif // SPECTRALSEG_EVALUATION_LABEL_FILES_H
