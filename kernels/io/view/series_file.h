// ParaView time series: one file per step and a series file naming them with their times, so that
// ParaView's Play button animates the steps (a curve's or surface's growth, level by level). Two forms,
// chosen by the name: "growth.pvd" (ParaView's XML Collection) and "growth.vtp.series" (ParaView's JSON
// file series; its reader is picked by the extension before ".series", so the name must carry it).
//
// The steps go to a folder named for the series ("growth.pvd" → growth/growth_000.vtp, ...), each written
// atomically; the series file is written last, so a reader never sees it name a step not yet there. A series
// written again into the same folder replaces the old one: step files of the old series that the new one
// does not name are removed (only files named as this series names its steps).
#pragma once

#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "kernels/io/format.h"
#include "kernels/io/save.h"

namespace selfsim::io {

// Whether `name` asks for a series (ends in .pvd or .series, any case).
bool is_series_name(const std::string& name);

// The extension of a series' step files: ".vtu" for NAME.vtu.series, else ".vtp". Throws Error for a bad name.
std::string series_step_extension(const std::string& name);

struct SeriesStep {
  ValueRef value;
  double time = 0;
};

struct SeriesFiles {
  std::string series;              // the series file written (root/name)
  std::vector<std::string> steps;  // each step's file, relative to root, in order
};

// The step file names a series file `name` uses for `count` steps, relative to root, and their extension.
std::vector<std::string> series_step_names(const std::string& name, std::size_t count);

// The text of a .pvd (ParaView's XML Collection) naming `files` (relative to it) at `times`.
std::string pvd_text(const std::vector<std::string>& files, std::span<const double> times);

// Writes the series. Throws Error for a bad name (".series" without a dataset extension before it, or one
// that is not .vtp/.vtu), no steps, times that are not finite and increasing, or anything save() refuses for
// a step (naming the step).
SeriesFiles save_series(std::span<const SeriesStep> steps, const std::filesystem::path& root, const std::string& name,
                        const SaveOptions& opt, Progress& progress);

// The step files a series file names, in the order it lists them (selfsim writes them by increasing time),
// as paths beside it: read back for `preview` and `info`, and to find the steps a rewrite replaces.
// Throws Error ("cannot read 'FILE': ...") for a file that is not a series, names no step, is over 64 MiB,
// or names a step outside its folder (an absolute path, or one through '..').
std::vector<std::filesystem::path> read_series_steps(const std::filesystem::path& series);
// The times a series file gives its steps, in its order; empty when a step's time is missing or not a finite
// number (the steps then go by their numbers). Throws Error as read_series_steps for a file it cannot read.
std::vector<double> read_series_times(const std::filesystem::path& series);

}  // namespace selfsim::io
