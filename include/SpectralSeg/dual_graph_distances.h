// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file dual_graph_distances.h
/// \brief Former name of `Weighted_dual_graph.h`, kept so that existing
/// includes keep working.
#ifndef SPECTRALSEG_DUAL_GRAPH_DISTANCES_H
#define SPECTRALSEG_DUAL_GRAPH_DISTANCES_H

#include <SpectralSeg/Weighted_dual_graph.h>

#endif // SPECTRALSEG_DUAL_GRAPH_DISTANCES_H
