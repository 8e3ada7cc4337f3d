-- A cube at index 2^30 + 4096, around the world origin through its transform: OpenVDB's coordinates would overflow
volume.vdb("far_index.vdb")
