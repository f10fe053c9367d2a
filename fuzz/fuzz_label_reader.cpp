// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// libFuzzer target of the label-file reader (`Evaluation::read_labels()`,
// used by `spectralseg eval` and `render`): the bytes of one label file are
// either refused with an Io_error naming it, or read as labels that the
// writer's format gives back (doc/hardening.md).
#include <SpectralSeg/Evaluation/label_files.h>
#include <SpectralSeg/exceptions.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

[[noreturn]] void broken(const char* what)
{
  std::fprintf(stderr, "fuzz_label_reader: broken invariant: %s\n", what);
  std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  SpectralSeg::IO::internal::File_bytes file;
  file.path = "fuzz.seg";
  file.data.assign(reinterpret_cast<const char*>(data), size);
  std::vector<int> labels;
  try
  {
    labels = SpectralSeg::Evaluation::internal::parse_labels(file);
  }
  catch(const SpectralSeg::Io_error& e)
  {
    if(std::string(e.what()).find(file.path) == std::string::npos)
      broken("an error message does not name the file");
    return 0;
  }
  if(labels.empty())
    broken("a file without labels was accepted");
  // the labels as write_labels() writes them read back the same
  SpectralSeg::IO::internal::File_bytes written;
  written.path = file.path;
  for(const int l : labels)
    written.data += std::to_string(l) + "\n";
  if(SpectralSeg::Evaluation::internal::parse_labels(written) != labels)
    broken("labels written one per line do not read back the same");
  return 0;
}
