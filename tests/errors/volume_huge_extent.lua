-- A box whose extent overflows double precision, saved with no voxel given: its default voxel (1/128 of
-- the longest side) would be inf; the message names the extent, not an option the recipe never set.
local b = volume.box { min = {-1e308, -1e308, -1e308}, max = {1e308, 1e308, 1e308} }
save(b, "huge.vdb")
