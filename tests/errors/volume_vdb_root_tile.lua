-- A .vdb level set whose cube is one active root tile of 4096^3 voxels (a 653-byte file, written by
-- tests/robustness/vdb_tiles.py): its surface is weighed before OpenVDB meshes it
volume.vdb("tiles_root.vdb")
