// Values as VTK pieces for the one VTK XML writer: curves as polyline cells, meshes as triangle cells,
// every field under its name. Curves also get two fields computed while writing, unless a kernel attached
// its own: point field `arclength` (distance along the path, restarting on each path) and cell field
// `path` (the path's index), so a user can colour any curve by them in ParaView.
#pragma once

#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/io/vtk/vtk_xml_writer.h"

namespace selfsim::io {

// `dataset` is PolyDataLines or UnstructuredGrid. The piece refers to c: keep c alive while it is written.
template <class V>
VtkPiece curve_piece(const PolylineT<V>& c, VtkDataset dataset);

// `dataset` is PolyDataPolys or UnstructuredGrid. The piece refers to m.
VtkPiece mesh_piece(const Mesh& m, VtkDataset dataset);

}  // namespace selfsim::io
