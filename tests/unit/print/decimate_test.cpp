// Decimation through VTK: a closed solid keeps closed with the triangles asked for, its shape kept; asking
// for as many triangles as it has, or fewer than 4, is refused.
#include "kernels/print/decimate.h"

#include <gtest/gtest.h>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/print/grid_thicken.h"

using namespace selfsim;
using namespace selfsim::print;

TEST(Decimate, AClosedSolidStaysClosed) {
  Mesh sheet;
  sheet.points = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}};
  sheet.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Mesh slab = thicken_on_grid(sheet, {.thickness = 2}, no_progress());
  ASSERT_GT(slab.faces(), 2000u);
  const Mesh fewer = decimate(slab, 1000, no_progress());
  EXPECT_TRUE(mesh_topology(fewer).closed());
  EXPECT_LE(fewer.faces(), 1000u);
  EXPECT_GE(fewer.faces(), 900u);
  EXPECT_NEAR(enclosed_volume(fewer), enclosed_volume(slab), 0.05 * enclosed_volume(slab));
  EXPECT_THROW(decimate(slab, static_cast<double>(slab.faces()), no_progress()), Error);
  EXPECT_THROW(decimate(slab, 3, no_progress()), Error);
}
