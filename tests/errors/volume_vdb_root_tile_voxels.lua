-- args: --max-points 1e9
-- The root tile's 2^36 voxels, weighed before any is made (volume.vdb keeps a level set's voxels)
volume.vdb("tiles_root.vdb")
