// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module's translation unit with what it would have compiled
// before the header splits of the compile-time work (doc/benchmarks.md,
// "Compile time"): the polygon triangulation of read_mesh_file(), and the
// two Boost max-flow backends that every graph cut compiled. Measured by
// benchmark/compile_time/measure.sh; not built by default.
#include "../../python/spectralseg_module.cpp"

#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/Refinement/graph_cut_boost_backends.h>

template SpectralSeg::IO::Mesh_file_report
SpectralSeg::IO::read_mesh_file<CGAL::Epick::Point_3>(const std::string&, CGAL::Surface_mesh<CGAL::Epick::Point_3>&);
