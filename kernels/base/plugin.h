// Parts of selfsim built as their own shared libraries and loaded on first use: OpenVDB, VTK's readers and
// VTK's renderer take milliseconds to tens of milliseconds to load and bind (libopenvdb alone resolves some
// 40,000 symbols), which every run would pay at start-up, even one that only draws a curve. A plugin exports
// one C function returning a table of pointers to its functions; the forwarding functions
// (kernels/plugins/openvdb_plugin.cpp, vtk_plugin.cpp, preview_plugin.cpp) keep the ordinary C++ interface
// (level_set.h, vdb_read.h, read.h, preview_png.h). Built with
// -DSELFSIM_PLUGINS=OFF (the fuzz build), the same code is linked in instead and none of this is used.
#pragma once

namespace selfsim {

// The table that `symbol` (an extern "C" function of no arguments) in plugin `library` ("selfsim_openvdb.so")
// returns, loading the library once. It is looked for beside the running executable, then in the build
// folder it was made in. Throws Error naming the library and why it could not be loaded.
const void* plugin_table(const char* library, const char* symbol);

}  // namespace selfsim
