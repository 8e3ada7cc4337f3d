// A Volume made concrete at a voxel size: its closed boundary mesh (for the exclusion surface's exact
// distances and for .vtp/.stl output), and the signed-distance level set a .vdb file holds. OpenVDB stays in
// level_set.cpp: its headers take a minute to compile.
#pragma once

#include <string>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/region/volume.h"

namespace selfsim {

// Budget points (16 bytes) the boundary of v at `voxel` takes to build: its triangles, and for a union or
// difference the narrow-band level sets (seven voxels across the boundary of every part) it comes from.
double boundary_size(const Volume& v, double voxel);

// The boundary of v as a closed triangle mesh facing outwards. A box is its 12 triangles, a sphere its
// sphere_mesh within voxel / 4, a mesh itself. A union or difference: each part converted to a level set
// (OpenVDB's meshToLevelSet, half width 3 voxels), combined (csgUnion, csgDifference), and meshed back
// (volumeToMesh, quads split along their shorter diagonal). Throws BudgetError over the budget, Error for a
// voxel size that is not positive and finite or for a combination that is empty at this voxel size.
Mesh volume_boundary(const Volume& v, double voxel, const PointBudget& budget, Progress& progress);

// The smallest voxel a .vdb file can hold: OpenVDB's transforms refuse a voxel whose cube is below 3e-15.
inline constexpr double min_vdb_voxel = 1.4423e-5;

// The signed distance to a closed mesh's surface (negative inside), or the unsigned distance to an open
// one, in a narrow band 3 voxels either side, as a .vdb file's bytes: one float grid named `name`, class
// "level set" for a closed mesh. Throws BudgetError over the budget, Error for a voxel below min_vdb_voxel.
std::string distance_vdb(const Mesh& m, bool closed, double voxel, const std::string& name, const PointBudget& budget,
                         Progress& progress);

}  // namespace selfsim
