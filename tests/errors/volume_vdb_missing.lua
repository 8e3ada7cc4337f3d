-- A .vdb region that is not there: where it was looked for, and the likeliest name.
local ball = volume.vdb("garbage_regin.vdb")
