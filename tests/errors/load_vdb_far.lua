-- Two blobs at index -2^29 and +2^29, where single-precision positions are 64 voxels apart
load("far_blobs.vdb")
