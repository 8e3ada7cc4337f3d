-- A 1 mm part modelled in metres: its default voxel (1/128 of the side) is below what any .vdb can hold.
local b = volume.box { min = {0,0,0}, max = {1e-3,1e-3,1e-3} }
save(b, "tiny.vdb")
