// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file label_files.h
/// \brief Reading and writing per-face label files (the Princeton
/// Segmentation Benchmark's `.seg` format: one integer per face).
#ifndef SPECTRALSEG_EVALUATION_LABEL_FILES_H
#define SPECTRALSEG_EVALUATION_LABEL_FILES_H

#include <SpectralSeg/IO/write_face_values.h>
#include <SpectralSeg/exceptions.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace SpectralSeg {
namespace Evaluation {

/// \ingroup PkgSpectralSegEvaluation
/// \brief Reads a label file: whitespace-separated integers (the benchmark's
/// `.seg` files have one per line), one per face in the file's face order.
/// \throws Io_error if the file cannot be opened or read, holds a token that
///         is not an integer in the range of `int`, or holds no label; the
///         message names the file (and the line of a bad token)
inline std::vector<int> read_labels(const std::string& path)
{
  std::ifstream in(path);
  if(!in)
    throw Io_error("cannot open label file '" + path + "'");
  std::vector<int> labels;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line))
  {
    ++line_number;
    std::size_t pos = 0;
    while(true)
    {
      pos = line.find_first_not_of(" \t\r\f\v", pos);
      if(pos == std::string::npos)
        break;
      const std::size_t end = std::min(line.find_first_of(" \t\r\f\v", pos), line.size());
      const std::string token = line.substr(pos, end - pos);
      pos = end;
      errno = 0;
      char* stop = nullptr;
      const long long v = std::strtoll(token.c_str(), &stop, 10);
      if(stop != token.c_str() + token.size() || errno == ERANGE || v < std::numeric_limits<int>::min() ||
         v > std::numeric_limits<int>::max())
        throw Io_error("label file '" + path + "', line " + std::to_string(line_number) + ": '" + token +
                       "' is not an integer label");
      labels.push_back(static_cast<int>(v));
    }
  }
  if(in.bad())
    throw Io_error("error while reading label file '" + path + "'");
  if(labels.empty())
    throw Io_error("label file '" + path + "' holds no label");
  return labels;
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
