// What save() needs beyond one file: the save options of a format, the run's record of the files it wrote (so
// that no two saves write one file, and the ParaView view knows them) and the time-series form of save().
#pragma once

#include <lua.hpp>
#include <span>
#include <string>

#include "kernels/io/format.h"
#include "kernels/io/save.h"
#include "kernels/io/view/paraview_view.h"

namespace selfsim::interp {

// The save() options of format f from the table at index (none there: the defaults).
// How the file `name` is being made, for the file to record (kernels/io/provenance/provenance.h): this selfsim, the
// recipe's absolute path and SHA-256, the run's --set values and seed.
std::string run_provenance(lua_State* L, const std::string& name);

io::SaveOptions read_save_options(lua_State* L, int index, const io::Format& f);

// `name` (relative to the output folder) lexically normal: the key saves are recorded under.
std::string normal_name(const std::string& name);
// Throws Error when this run has already written the file `name` names.
void check_not_saved(lua_State* L, const std::string& name);
// Records a file written by save().
void record_saved(lua_State* L, const std::string& name);

// Whether f is a VTK format the view shows (.vtp, .vtu), and the role a value has there.
bool is_vtk(const io::Format& f);
io::ViewRole role_of(const io::ValueRef& v);
// Records a VTK file or series written (its steps), for the run's ParaView view.
void record_view(lua_State* L, const std::string& name, io::ViewRole role, std::span<const io::ValueRef> steps,
                 bool series);

// save(list or value, "growth.pvd" | "growth.vtp.series", opts?): bind_series.cpp.
int save_series(lua_State* L);

}  // namespace selfsim::interp
