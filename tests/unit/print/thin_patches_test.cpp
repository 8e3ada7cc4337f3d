// Thin places are patches of faces joined at shared corners, each with its own area.
#include "kernels/print/thin_patches.h"

#include <gtest/gtest.h>

#include "kernels/geom/mesh.h"
#include "kernels/region/box_mesh.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

// The faces of a 10 mm cube whose normals point along `axis` (either way), flagged.
std::vector<char> sides_along(const Mesh& m, int axis, double sign) {
  std::vector<char> flagged(m.faces(), 0);
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const Vec3 n = area_normal(m, m.triangles[f]);
    const double along = axis == 0 ? n.x : axis == 1 ? n.y : n.z;
    flagged[f] = sign * along > 0;
  }
  return flagged;
}

}  // namespace

TEST(ThinPatches, FacesSharingCornersAreOnePlaceAndApartAreTwo) {
  const Mesh cube = box_mesh({0, 0, 0}, {10, 10, 10});
  const Patches top = thin_patches(cube, sides_along(cube, 2, 1));
  EXPECT_EQ(top.count, 1u);
  EXPECT_NEAR(top.largest, 100, 1e-9);
  // Top and bottom share no corner: two places of 100 mm² each, not one of 200.
  std::vector<char> both = sides_along(cube, 2, 1);
  const std::vector<char> bottom = sides_along(cube, 2, -1);
  for (std::size_t f = 0; f < both.size(); ++f) both[f] |= bottom[f];
  const Patches apart = thin_patches(cube, both);
  EXPECT_EQ(apart.count, 2u);
  EXPECT_NEAR(apart.largest, 100, 1e-9);
  // A side joins them at its corners: one place of 300 mm².
  const std::vector<char> side = sides_along(cube, 0, 1);
  for (std::size_t f = 0; f < both.size(); ++f) both[f] |= side[f];
  const Patches joined = thin_patches(cube, both);
  EXPECT_EQ(joined.count, 1u);
  EXPECT_NEAR(joined.largest, 300, 1e-9);
  EXPECT_EQ(thin_patches(cube, std::vector<char>(cube.faces(), 0)).count, 0u);
}
