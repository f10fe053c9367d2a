// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The method templates instantiated with their default policies, compiled
// once for the programs of a build with SPECTRALSEG_SEPARATE_COMPILATION
// (the CMake target SpectralSeg_compiled, with src/spectralseg_compiled.cpp;
// include/SpectralSeg/internal/separate_compilation.h). Every header that
// writes SPECTRALSEG_INSTANTIATE is included here.
#ifndef SPECTRALSEG_SEPARATE_COMPILATION
#error "src/spectralseg_instances.cpp is compiled with SPECTRALSEG_SEPARATE_COMPILATION (CMake target SpectralSeg_compiled)"
#endif
#ifndef SPECTRALSEG_COMPILING_INSTANCES
#define SPECTRALSEG_COMPILING_INSTANCES
#endif

#include <SpectralSeg/IO/read_mesh_file.h>
#include <SpectralSeg/IO/triangle_soup_to_mesh.h>
#include <SpectralSeg/Metrics/Part_aware_weight.h>
#include <SpectralSeg/Metrics/VSI_weight.h>
#include <SpectralSeg/automatic_segmentation.h>
#include <SpectralSeg/segment_hybrid.h>
#include <SpectralSeg/segment_k_way.h>
