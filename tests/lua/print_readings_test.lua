-- solid.check's numbers are what was measured: a slab the grid resolves reads its thickness; one finer than
-- the grid reads the bound it is known to be under (two voxels), with wall_resolved = false, never the
-- rays' first-step number.
local function slab(t)  -- a closed 20 x 20 mm box t mm thick
  return mesh { points = { { 0, 0, 0 }, { 20, 0, 0 }, { 20, 20, 0 }, { 0, 20, 0 },
                           { 0, 0, t }, { 20, 0, t }, { 20, 20, t }, { 0, 20, t } },
                triangles = { { 1, 3, 2 }, { 1, 4, 3 }, { 5, 6, 7 }, { 5, 7, 8 }, { 1, 2, 6 }, { 1, 6, 5 },
                              { 2, 3, 7 }, { 2, 7, 6 }, { 3, 4, 8 }, { 3, 8, 7 }, { 4, 1, 5 }, { 4, 5, 8 } } }
end

local thick = solid.check(slab(1.0), { profile = "fdm", voxel = 0.1 })
assert(thick.wall_resolved == true, "a 1 mm slab is resolved")
assert(math.abs(thick.thinnest_wall - 1.0) < 0.05, "a 1 mm slab reads " .. thick.thinnest_wall)

local thin = solid.check(slab(0.03), { profile = "fdm", voxel = 0.1 })
assert(thin.wall_resolved == false, "a 0.03 mm slab is finer than a 0.1 mm grid resolves")
assert(math.abs(thin.thinnest_wall - 0.2) < 1e-9, "its reading is the bound, two voxels: " .. thin.thinnest_wall)
assert(not thin.passes)

-- Issue 40: each finding's severity and fix, and the overhang, in the report.
assert(#thin.problems >= 1, "a thin slab has problems")
assert(thin.problems[1].severity == "will fail", "walls under the nozzle will fail: " .. thin.problems[1].severity)
assert(thin.problems[1].fix:find("thickness = 0.8", 1, true), thin.problems[1].fix)
assert(thin.summary:find("will fail: walls thinner", 1, true), thin.summary)
assert(thick.overhang == 0, "a slab on the bed overhangs nothing: " .. thick.overhang)
assert(thick.summary:find("no overhang past 45°", 1, true), thick.summary)

-- One check per solid: solid.thicken's warning check is shared by solid.check (and save's summary), which
-- measures nothing again (reused) and still marks the solid with wall, gap and overhang.
local sheet = mesh { points = { { 0, 0, 0 }, { 20, 0, 0 }, { 20, 20, 0 }, { 0, 20, 0 } },
                     triangles = { { 1, 2, 3 }, { 1, 3, 4 } } }
local plate = solid.thicken(sheet, { thickness = 2 })
local report, marked = solid.check(plate)
assert(report.reused == true, "solid.check after solid.thicken measures again")
assert(report.passes, report.summary)
local names = table.concat(marked:fields().cells, " ")
for _, f in ipairs({ "wall", "gap", "overhang" }) do assert(names:find(f, 1, true), "no face field " .. f .. ": " .. names) end
-- Other rules are another check; checking again with them is then shared too.
local sla = solid.check(plate, { profile = "sla" })
assert(sla.reused == false, "the sla check is a new one")
assert(solid.check(plate, { profile = "sla" }).reused == true, "the same sla check twice measures twice")
assert(solid.check(plate, { overhang = 30 }).reused == false, "another overhang angle is another check")
