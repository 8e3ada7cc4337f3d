// The inside of a closed mesh's distance grid from its winding number, not from OpenVDB's flood fill.
//
// Why: OpenVDB's meshToVolume signs a voxel by sweeping in from outside through voxels more than 0.75 voxel
// from every triangle; a voxel nearer a triangle turns "outside" only beside one already outside, and one
// left "inside" between two surfaces is then removed as a self-intersection. So a gap narrower than about
// 2.5 voxels (two slabs 0.2 mm apart at a 0.133 mm voxel), and everything behind it, becomes solid: the gap
// reads as nothing. The winding number (how many times the surface wraps a point, counted along a lattice
// line) needs no path in from outside: a voxel centre in a gap of any width is outside. Overlapping parts
// still read as one solid (winding 2 is inside), a sealed cavity as empty (its inward faces bring the
// winding back to 0).
#pragma once

#include "kernels/geom/mesh.h"
#include "kernels/plugins/openvdb/grid_frame.h"

namespace selfsim::vdb {

// Makes g (m's unsigned distance in frame f, voxel 1: mesh_grid's for an open mesh) m's level set: every
// active value negative where m's winding number at its voxel centre is not 0, inactive values and tiles
// signed from the active ones (signedFloodFill). m is closed; its facing does not matter.
void sign_by_winding(Grid& g, const Mesh& m, const Frame& f, Interrupter& interrupt);

}  // namespace selfsim::vdb
