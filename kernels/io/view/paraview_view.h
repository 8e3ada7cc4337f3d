// A ParaView view of a run's VTK outputs, written beside them as view.py: `paraview --script=view.py` opens
// every dataset coloured by its natural field (natural_field.h), class fields in categorical colours, a
// region's walls see-through, a curve with a point field `width` as tubes of radius proportional to it, 3D
// seen as the preview's oblique view with its up axis up (up_axis.h), the camera fitted and time series wired
// to the animation; `pvbatch view.py
// --png view.png` renders the same picture without a window. A Python script through paraview.simple
// rather than a .pvsm state: paraview.simple's calls have stayed the same across ParaView 5.x, while a
// state file spells out every proxy's XML, which changes from version to version.
#pragma once

#include <filesystem>
#include <span>
#include <string>

#include "kernels/io/view/natural_field.h"

namespace selfsim::io {

enum class ViewRole { curve, surface, region };

struct ViewDataset {
  std::string file;  // relative to the output folder: "dragon.vtp", "growth.pvd"
  std::string name;  // as ParaView's pipeline shows it
  ViewRole role = ViewRole::curve;
  bool series = false;
  bool flat = true;  // every point at z = 0
  int up = 1;        // the axis drawn up in 3D (up_axis.h): 0, 1, 2 for x, y, z
  Colouring colouring;
};

// Whether view.py can name the dataset: its file, name and field are UTF-8 text (Python reads its source
// as UTF-8, and ParaView opens a path given as text).
bool view_can_name(const ViewDataset& d);

// The text of view.py for `datasets` in the folder `folder` (absolute: the GUI runs a script without
// telling it where it is). Datasets view_can_name refuses are left out.
std::string paraview_view_text(std::span<const ViewDataset> datasets, const std::filesystem::path& folder);

// Writes it to root/name atomically and returns the path written.
// `named`, when given, is the folder the script names instead of root: `run --watch` writes into a staging
// folder whose files it then moves into the output folder.
std::string write_paraview_view(std::span<const ViewDataset> datasets, const std::filesystem::path& root,
                                const std::string& name, const std::filesystem::path& named = {});

}  // namespace selfsim::io
