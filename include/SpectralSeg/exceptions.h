// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file exceptions.h
/// \brief The exceptions thrown by SpectralSeg.
#ifndef SPECTRALSEG_EXCEPTIONS_H
#define SPECTRALSEG_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace SpectralSeg {

/// \ingroup PkgSpectralSegCore
/// \brief Base class of every exception thrown by SpectralSeg.
class Error : public std::runtime_error
{
public:
  /// \param what the message
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

/// \ingroup PkgSpectralSegCore
/// \brief Thrown when an input mesh or a parameter cannot be used:
/// non-triangle faces given to an algorithm that needs triangles, non-finite
/// coordinates, an out-of-range face, a weight vector of the wrong size, a
/// negative or non-finite edge weight, and so on. The message says which.
class Invalid_input : public Error
{
public:
  /// \param what the message
  explicit Invalid_input(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSpectralSegCore
/// \brief Thrown when a file cannot be opened, read or written.
class Io_error : public Error
{
public:
  /// \param what the message
  explicit Io_error(const std::string& what) : Error(what) {}
};

/// \ingroup PkgSpectralSegCore
/// \brief Thrown when a progress callback asked to stop a computation.
/// No output property map is written when this is thrown.
class Operation_cancelled : public Error
{
public:
  /// \param stage the stage that was running
  explicit Operation_cancelled(const std::string& stage)
    : Error("operation cancelled during stage '" + stage + "'"), stage_(stage) {}
  /// the stage that was running when the computation stopped
  const std::string& stage() const { return stage_; }

private:
  std::string stage_;
};

} // namespace SpectralSeg

#endif // SPECTRALSEG_EXCEPTIONS_H
