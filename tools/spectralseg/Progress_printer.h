// Copyright (c) 2026 SpectralSeg developers.
// SPDX-License-Identifier: GPL-3.0-or-later
// A progress indicator on stderr for the command-line tool.
#ifndef SPECTRALSEG_TOOLS_PROGRESS_PRINTER_H
#define SPECTRALSEG_TOOLS_PROGRESS_PRINTER_H

#include <SpectralSeg/Execution.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <unistd.h>

namespace spectralseg_cli {

// Prints "stage: NN%" lines on stderr, at most one per stage and percent
// step, and "stage: done (T s)" at the end of each stage. Silent if quiet.
class Progress_printer
{
public:
  explicit Progress_printer(bool quiet) : quiet_(quiet), tty_(isatty(fileno(stderr)) != 0) {}

  SpectralSeg::Progress_callback callback()
  {
    if(quiet_)
      return {};
    return [this](const std::string& stage, double fraction) {
      update(stage, fraction);
      return true;
    };
  }

  void message(const std::string& text) const
  {
    if(!quiet_)
      std::fprintf(stderr, "%s\n", text.c_str());
  }

private:
  void update(const std::string& stage, double fraction)
  {
    const auto now = std::chrono::steady_clock::now();
    if(stage != stage_)
    {
      stage_ = stage;
      start_ = now;
      last_percent_ = -1;
    }
    const int percent = static_cast<int>(fraction * 100.);
    if(percent == last_percent_)
      return;
    last_percent_ = percent;
    if(percent >= 100)
      std::fprintf(stderr, "%s%-32s done (%.2f s)\n", tty_ ? "\r" : "", stage.c_str(),
                   std::chrono::duration<double>(now - start_).count());
    else if(tty_ && percent % 10 == 0) // redirected output gets the final line only
      std::fprintf(stderr, "\r%-32s %3d%%", stage.c_str(), percent);
    std::fflush(stderr);
  }

  bool quiet_;
  bool tty_;
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
  int last_percent_ = -1;
};

} // namespace spectralseg_cli

#endif
