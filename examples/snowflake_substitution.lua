-- Seed 003: the Koch snowflake by path substitution on complex numbers. Each segment of a triangle is
-- replaced by the four-segment generator, again and again.
local levels = param("levels", 5)
local s3 = math.sqrt(3)
local triangle = polygon { { 0, 0 }, { 1, 0 }, { 0.5, s3 / 2 } }
local generator = polyline { { 0, 0 }, { 1 / 3, 0 }, { 0.5, -s3 / 6 }, { 2 / 3, 0 }, { 1, 0 } }
local flake = substitute { path = triangle, generator = generator, levels = levels }
save(flake, "snowflake.vtp")
save(flake, "snowflake.svg", { fill = "#a8dadc" })

-- Seed 000 Figure 2: the same generator with its middle segments flipped gives a different curve.
local variant = substitute {
  path = polyline { { 0, 0 }, { 1, 0 } }, generator = generator, levels = levels,
  transforms = { "identity", "reflect_segment", "reflect_bisector", "identity" },
}
save(variant, "koch_variant.svg")
