-- A .vdb region that is not an OpenVDB file: one line naming it.
local ball = volume.vdb("garbage_region.vdb")
