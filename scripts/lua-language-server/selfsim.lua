---@meta _
-- The selfsim recipe DSL for lua-language-server (LuaLS, the "Lua" extension of VS Code, Neovim's lua_ls):
-- completion, hover docs and type checks in recipes. A definition file only: nothing here runs, and the
-- interpreter never loads it (its folder name is not a valid module name). `---@meta _` keeps `require`
-- from resolving to it; the modules have their own files beside it (selfsim/curves.lua, selfsim/sheet.lua),
-- since one meta file answers to one require name.
--
-- The functions are selfsim's own (frontend/bindings/bind_*.cpp, frontend/lua/value_types.cpp); what they do in full is in docs/*.md. The test cli.meta (tests/meta/) checks this file
-- against what the interpreter registers: every global, every field of a global table and of a module, and
-- every method of every value type, missing or extra, fails it. Its parser reads these shapes only, one
-- declaration per line, so keep to them:
--   function name(...) end                   a global function
--   name = {}                                a global table, then  function name.field(...) end
--                                            (or  name.field = value  for a field that is no function)
--   ---@class selfsim.Type[: selfsim.Base]   a value type, the next line  local Type = {},
--                                            then  function Type:method(...) end; a class that others
--                                            inherit from (selfsim.Value) lends them its methods
--   ---@meta selfsim.module ... local M = {} ... function M.f(...) end ... return M
--                                            a module's file, selfsim/<module>.lua
-- Option and report tables are plain ---@class blocks with ---@field lines (not checked by the test).

-- Small tables ------------------------------------------------------------------------------------------

---A bounding box: { min = {x, y[, z]}, max = {...} }.
---@class selfsim.BBox
---@field min number[]
---@field max number[]

---The names of the fields a value carries.
---@class selfsim.FieldNames
---@field points string[] point fields
---@field cells string[] cell fields (a curve's paths, a mesh's triangles)

---A value's levels: the value as it was at each level (the last is the value itself), and their numbers.
---@class selfsim.Levels
---@field times integer[] the level (or generation) of each entry
---@field [integer] selfsim.Value

-- Enumerations, for completion of option values ---------------------------------------------------------

---@alias selfsim.Boundary "clamp"|"repeat"|"reflect_y"|"reflect_x"|"rotate"
---A segments mode of hoist.multiply/iterate: every copy as is, or every other copy transformed.
---@alias selfsim.SegmentsMode "repeat"|"reflect_y"|"reflect_x"|"rotate"
---One copy's transform in a segments list.
---@alias selfsim.CopyTransform "identity"|"reflect_x"|"reflect_y"|"rotate"
---substitute{}'s per-segment transforms (Kaplan's four).
---@alias selfsim.SegmentTransform "identity"|"reflect_segment"|"reflect_bisector"|"half_turn"
---@alias selfsim.Stencil "loop"|"bounded"
---A printer profile of the print check.
---@alias selfsim.Profile "fdm"|"sla"
---A colour: a CSS name ("steelblue"), "#rgb", "#rrggbb" or "none".
---@alias selfsim.Colour string

-- Values ------------------------------------------------------------------------------------------------

---What every geometry value (Curve, Curve3, Mesh) has. Big geometry stays in C++: these give counts,
---boxes and single points, never bulk tables.
---@class selfsim.Value
local Value = {}

---The number of points.
---@return integer
function Value:points() end

---The i-th point (1-based) as {x, y} or {x, y, z}, for checks in recipes.
---@param i integer
---@return number[]
function Value:point(i) end

---The bounding box, { min = {...}, max = {...} }.
---@return selfsim.BBox
function Value:bbox() end

---The fields the value carries, { points = {names}, cells = {names} }.
---@return selfsim.FieldNames
function Value:fields() end

---The smallest and largest value of a field's first component (a point field first, then a cell field,
---unless `where` says which).
---@param name string
---@param where? "points"|"cells"
---@return number min
---@return number max
function Value:range(name, where) end

---The value at each level of the kernel that grew it (exclusion, L-system, substitution, hoisting,
---develop); an error for a value that has no levels (transformed, joined, loaded).
---@return selfsim.Levels
function Value:levels() end

---The value as it was at level k (see levels()).
---@param k integer
---@return selfsim.Value
function Value:level(k) end

---A 2D curve: one or more polyline paths with named point and cell fields.
---@class selfsim.Curve: selfsim.Value
local Curve = {}

---The number of segments, over all paths.
---@return integer
function Curve:segments() end

---The number of paths.
---@return integer
function Curve:paths() end

---The total length of every path.
---@return number
function Curve:length() end

---Without k: the level a kernel recorded for the whole curve, or nil. With k: the curve at level k.
---@param k? integer
---@return integer|selfsim.Curve|nil
function Curve:level(k) end

---The curve at each level of the kernel that grew it.
---@return { [integer]: selfsim.Curve, times: integer[] }
function Curve:levels() end

---A new curve: mirrored across the x axis, scaled about the origin, rotated by degrees counterclockwise,
---then translated, in that order.
---@param options selfsim.TransformOptions
---@return selfsim.Curve
function Curve:transform(options) end

---The same points walked from the end (paths in reverse order, each reversed), fields following.
---@return selfsim.Curve
function Curve:reverse() end

---Every corner replaced by the circular arc tangent to its two segments (Irving & Segerman §1).
---@param options? selfsim.RoundedOptions
---@return selfsim.Curve
function Curve:rounded(options) end

---A 3D curve: one or more polyline paths in space (the 3D turtle, polyline{} of {x, y, z} points).
---@class selfsim.Curve3: selfsim.Value
local Curve3 = {}

---The number of segments, over all paths.
---@return integer
function Curve3:segments() end

---The number of paths.
---@return integer
function Curve3:paths() end

---The total length of every path.
---@return number
function Curve3:length() end

---Without k: the level a kernel recorded for the whole curve, or nil. With k: the curve at level k.
---@param k? integer
---@return integer|selfsim.Curve3|nil
function Curve3:level(k) end

---The curve at each level of the kernel that grew it.
---@return { [integer]: selfsim.Curve3, times: integer[] }
function Curve3:levels() end

---A new curve: mirrored across the xz-plane (y negated), scaled about the origin, rotated by degrees about
---`axis`, then translated.
---@param options selfsim.Transform3Options
---@return selfsim.Curve3
function Curve3:transform(options) end

---The same points walked from the end (paths in reverse order, each reversed), fields following.
---@return selfsim.Curve3
function Curve3:reverse() end

---A triangle mesh with named point and face fields.
---@class selfsim.Mesh: selfsim.Value
local Mesh = {}

---The number of triangles.
---@return integer
function Mesh:faces() end

---The mesh as it was at level k (see levels()).
---@param k integer
---@return selfsim.Mesh
function Mesh:level(k) end

---The mesh at each level of the kernel that grew it.
---@return { [integer]: selfsim.Mesh, times: integer[] }
function Mesh:levels() end

---A new mesh: scaled about the origin (a factor, or one per axis; a negative one mirrors, the triangles
---turned to keep facing outwards), rotated by degrees about `axis`, then translated. `normal` fields turn
---with the faces; length fields (`thickness`, `wall`, ...) scale with a uniform factor.
---@param options selfsim.MeshTransformOptions
---@return selfsim.Mesh
function Mesh:transform(options) end

---@class selfsim.MeshTransformOptions
---@field scale? number|number[] a factor or {sx, sy, sz}, never zero; negative mirrors (1)
---@field rotate? number degrees about `axis`, counterclockwise seen from where it points (0)
---@field axis? number[] {x, y, z} ({0, 0, 1})
---@field translate? number[] {x, y, z} ({0, 0, 0})

---An L-system grammar, made by lsystem{} or the functions of selfsim.curves.
---@class selfsim.Grammar
local Grammar = {}

---The turtle's curve at a level: a Curve, or a Curve3 for the 3D turtle. A plant (a grammar that branches
---or draws in 3D) stays as the turtle draws it, from the origin heading up (+y); other open curves are
---normalised to run from (0,0) to (1,0). normalize, when given, decides instead.
---@param options integer|selfsim.TurtleOptions the level, or { level = n, normalize = true }
---@return selfsim.Curve|selfsim.Curve3
function Grammar:curve(options) end

---The { . } polygons of a level as a mesh, placed as the 3D curve is (pass the same normalize as to curve).
---@param options integer|selfsim.TurtleOptions the level, or { level = n, normalize = true }
---@return selfsim.Mesh
function Grammar:polygons(options) end

---The level's string, for small levels (up to 10 million symbols).
---@param level integer
---@return string
function Grammar:string(level) end

---The predicted number of segments at a level, without drawing it.
---@param level integer
---@return integer
function Grammar:count(level) end

---A region of space: a box, a sphere, a closed mesh, a .vdb level set, or their unions and differences.
---@class selfsim.Volume
local Volume = {}

---The bounding box, { min = {x, y, z}, max = {x, y, z} }.
---@return selfsim.BBox
function Volume:bbox() end

---The closed boundary surface a run measures distances to, at the volume's voxel size or the one given.
---@param options? selfsim.VoxelOptions
---@return selfsim.Mesh
function Volume:boundary(options) end

-- Options and reports -------------------------------------------------------------------------------------

---@class selfsim.ParamOptions
---@field min? number the smallest value --set may give (numbers only)
---@field max? number the largest value --set may give (numbers only)
---@field step? number the step of a slider or a sweep, > 0 (numbers only)
---@field doc? string one line saying what the parameter does
---@field choices? string[] the values a string parameter may take

---save()'s options; which ones a format reads depends on its extension.
---@class selfsim.SaveOptions
---@field stroke? selfsim.Colour|selfsim.Colour[] .svg/.eps: line colour, or a palette cycled over a group's members
---@field stroke_width? number|number[] .svg/.eps: line width in pixels (in the size's unit with a physical size)
---@field fill? selfsim.Colour|selfsim.Colour[] .svg/.eps: fill colour (even-odd rule), "none" by default
---@field size? number|string .svg/.eps: pixels of the longer side (800), or a length such as "150mm", "15cm", "6in"
---@field voxel? number .vdb: the voxel size (default 1/128 of the longest side)
---@field name? string .3mf: the object's name (default the file's)

---A group member with its own SVG style: { curve, stroke = ..., stroke_width = ..., fill = ... }.
---@class selfsim.StyledMember
---@field [1] selfsim.Curve|selfsim.Curve3
---@field stroke? selfsim.Colour
---@field stroke_width? number
---@field fill? selfsim.Colour

---@class selfsim.LsystemOptions
---@field axiom string level 0: symbols, or modules with parameters ("A(1, 0.5) B")
---@field rules? table<string, string|table>|string[]|string { X = "X-YF" }, weighted choices, ABOP rule strings
---@field angle? number degrees turned by + and - (90)
---@field angles? table<string, number> per-symbol turns in degrees, positive = left
---@field start_angle? number|number[] initial heading in degrees, or a list cycled by level
---@field shrink? number step length is shrink^level (1)
---@field draw? string symbols that step forward drawing ("FG")
---@field move? string symbols that step forward without drawing ("f")
---@field seed? integer seed of the stochastic choices (default --seed)
---@field ignore? string symbols a context skips over (default the turns)
---@field define? table<string, number> named constants the rules' expressions may read
---@field decomposition? table|string rules applied to every module a step writes, recursively
---@field interpretation? table|string rules applied only when drawing
---@field max_depth? integer how deep decomposition and interpretation recurse, 0 to 64 (8)
---@field dimension? 2|3 the 2D or 3D turtle (default: 3D when the grammar writes & ^ \ / $ or has a tropism)
---@field tropism? number[] 3D: {x, y, z}, the heading bends toward it after every step
---@field level? integer the level g:curve(), g:string() and g:count() draw when given none (the book's derivation length)

---@class selfsim.TurtleOptions
---@field level integer the rewriting level
---@field normalize? boolean map an open curve onto (0,0)-(1,0) (default: true, false for a plant)

---@class selfsim.TransformOptions
---@field mirror? boolean mirror across the x axis first (false)
---@field scale? number scale about the origin (1)
---@field rotate? number degrees counterclockwise (0)
---@field translate? number[] {x, y} added last

---@class selfsim.Transform3Options
---@field mirror? boolean mirror across the xz-plane first (false)
---@field scale? number scale about the origin (1)
---@field rotate? number degrees about axis (0)
---@field axis? number[] {x, y, z}, the rotation axis ({0, 0, 1})
---@field translate? number[] {x, y, z} added last

---@class selfsim.RoundedOptions
---@field samples? integer segments per quarter turn of an arc, 1 to 1024 (8)

---@class selfsim.MeshOptions
---@field points number[][] {x, y, z} points
---@field triangles integer[][] {i, j, k} 1-based point indices, counter-clockwise seen from outside

---@class selfsim.SubstituteOptions
---@field path selfsim.Curve|number[][] the curve whose segments are replaced
---@field generator selfsim.Curve|number[][] the path that replaces each segment, from (0,0) to (1,0)
---@field levels integer how many times to substitute, 0 to 64
---@field transforms? selfsim.SegmentTransform[] one per generator segment

---@class selfsim.SplineOptions
---@field points number[][] control points, from {0, 0} to {1, 0}
---@field flatness? number how far a span may stray from a sample chord, 1e-9 to 0.1 (1e-4)
---@field normalize? boolean map the first and last control points to (0,0) and (1,0) (false)

---@class selfsim.OntoOptions
---@field boundary? selfsim.Boundary how P extends beyond its ends ("clamp")

---@class selfsim.MultiplyOptions
---@field segments? selfsim.SegmentsMode|selfsim.CopyTransform[] a mode, or one transform per copy ("repeat")

---@class selfsim.IterateOptions
---@field multiplicity number copies of the curve per generation
---@field generations integer rounds of multiplying and hoisting, 0 to 64
---@field boundary? selfsim.Boundary ("clamp")
---@field segments? selfsim.SegmentsMode|selfsim.CopyTransform[] ("repeat")

---@class selfsim.DevelopOptions
---@field levels? integer the finest level (required for a grammar; level 0 is the axiom)
---@field method? "loop"|"bezier" route 1, the control mesh Loop-smoothed, or route 2, Bezier arcs ("loop")
---@field height? number gap between levels l and l+1, in mean segment lengths of level l (1)
---@field smooth? integer route 1: rounds of Loop subdivision, 0 to 12 (0)
---@field stencil? selfsim.Stencil route 1: classic weights or bounded curvature ("loop")
---@field corner_shift? number route 1: inner points moved this fraction (0 to 0.5) to their neighbours' middle
---@field resolution? integer route 2: samples per Bezier piece, 1 to 64 (4)
---@field thickness? number thickness at level 0 in curve units: a closed solid instead of the open surface
---@field thickness_rate? number factor per level in [1e-6, 1] (default the curve's own)
---@field size? number scale so the largest side (or level size_level's curve) is this many mm
---@field size_level? integer the level whose curve `size` measures
---@field check? boolean refuse a surface that meets itself (true)

---@class selfsim.ExclusionCurveOptions
---@field region selfsim.Curve|number[][] a closed curve, or a group: the outer ring first, then the holes
---@field start selfsim.Curve|number[][] a curve whose paths are the start curves
---@field radius number the first level's exclusion radius, > 0
---@field factor? number the radius is multiplied by this at each level, in (0, 1] (0.8)
---@field levels integer how many times every segment is split, 0 to 40
---@field order? "breadth"|"depth" ("breadth")
---@field scan? "alternate"|"forward" breadth only ("alternate")
---@field exclusion? "exact"|"vertex"|"original" segment to segment, or Bowyer's own program's rule ("exact")

---One level of an exclusion curve's or surface's report.
---@class selfsim.LevelReport
---@field triangles? integer surfaces: triangles after the level
---@field splits? integer curves: segments split
---@field moves? integer surfaces: points moved
---@field stuck integer points that could not move
---@field seconds number
---@field area? number surfaces: the area after the level

---@class selfsim.ExclusionCurveReport
---@field stuck integer points that could not move, over all levels
---@field levels selfsim.LevelReport[]

---@class selfsim.DiscsOptions
---@field radius number the curve's first exclusion radius
---@field factor? number the curve's factor (0.8)
---@field level? integer only the points made at this level (1 to 40)
---@field samples? integer corners of each disc, 3 to 4096 (32)

---@class selfsim.ExclusionSurfaceOptions
---@field region selfsim.Volume the volume to fill
---@field start selfsim.Mesh|number[][] a mesh, or one triangle's three {x, y, z} points
---@field radius number the first level's exclusion radius
---@field factor? number the radius is multiplied by this at each level, in (0, 1] (0.8)
---@field levels integer how many times every triangle is split in four, 0 to 20
---@field exclusion? "neighbourhood"|"strict" what a move must keep ("neighbourhood")
---@field neighbourhood? number the own neighbourhood, in radii along the surface (6)
---@field near? number how near, as a fraction of the radius, own-neighbourhood pieces may come (0.01)
---@field walls? "mesh"|"grid" measure the walls on the region's triangles or its distance grid ("mesh")

---@class selfsim.ExclusionSurfaceReport
---@field stuck integer points that could not move, over all levels
---@field voxel number the voxel size the region's boundary was made at
---@field region_triangles integer
---@field walls "mesh"|"grid"
---@field wall_error? number walls = "grid": how far the grid's distances may be off
---@field levels selfsim.LevelReport[]

---@class selfsim.DimensionOptions
---@field method? "length"|"box" length scaling (exclusion curves) or box counting ("length")
---@field from? integer the first level or box step
---@field to? integer the last level or box step

---@class selfsim.DimensionPoint
---@field step integer
---@field x number
---@field y number

---@class selfsim.Dimension
---@field method "length"|"box"
---@field dimension number
---@field slope number
---@field intercept number
---@field error? number the slope's standard error (absent from two points)
---@field points selfsim.DimensionPoint[]

---@class selfsim.VoxelOptions
---@field voxel? number the voxel size every use of the volume takes

---@class selfsim.BoxOptions: selfsim.VoxelOptions
---@field min number[] the lowest corner {x, y, z}
---@field max number[] the highest corner {x, y, z}

---@class selfsim.SphereOptions: selfsim.VoxelOptions
---@field center number[] {x, y, z}
---@field radius number

---@class selfsim.VdbOptions: selfsim.VoxelOptions
---@field grid? string the grid whose surface to take (default the first level set)

---A list of volumes, and optionally the voxel size: { a, b, voxel = v }.
---@class selfsim.VolumeList: selfsim.VoxelOptions
---@field [integer] selfsim.Volume

---What solid.* does about the print check: true (fdm), false, or a profile.
---@alias selfsim.Check boolean|selfsim.Profile

---@class selfsim.ThickenOptions
---@field thickness number the solid's thickness in mm
---@field method? "sheets"|"grid" offset sheets and a rim, or an OpenVDB distance grid ("sheets")
---@field voxel? number grid: the voxel size (a quarter of the thickness)
---@field adaptivity? number grid: 0 to 1, fewer triangles where flat (0)
---@field check? selfsim.Check (true)

---@class selfsim.TubeOptions
---@field radius number the tube's radius in mm
---@field method? "rings"|"grid" rings on rotation-minimising frames, or round cones merged on a grid ("rings")
---@field sides? integer rings: sides of each ring, 3 to 256 (16)
---@field by? string a point field multiplying the radius ("width": a plant's '!'); on the grid, round cones
---@field taper? number with `by`, the radius is radius * taper^field
---@field min_radius? number no radius below this, mm (none)
---@field voxel? number grid: the voxel size (a quarter of the thinnest radius, coarser to fit the budget)
---@field adaptivity? number grid: 0 to 1 (0)
---@field check? selfsim.Check (true)

---@class selfsim.ReliefOptions
---@field height number the relief's height in mm
---@field base? number the base plate's thickness in mm (none)
---@field margin? number the plate's border beyond the outline's box, mm (5 % of its size)
---@field check? selfsim.Check (true)

---@class selfsim.SmoothOptions
---@field steps? integer rounds of Loop subdivision, 0 to 12 (1)
---@field stencil? selfsim.Stencil ("loop")
---@field meets? boolean keep a result that meets itself (false)
---@field check? selfsim.Check (true)

---@class selfsim.DecimateOptions
---@field triangles integer how many triangles to keep
---@field check? selfsim.Check (true)

---@class selfsim.SizeOptions
---@field size? number the size in mm of the largest side (or of `axis`)
---@field axis? "x"|"y"|"z" the side `size` measures
---@field fit? number[] {x, y, z} mm: the largest size that fits this box

---@class selfsim.CheckOptions
---@field profile? selfsim.Profile ("fdm")
---@field nozzle? number mm
---@field min_wall? number mm
---@field min_gap? number mm
---@field triangles? number the triangle budget (2,000,000)
---@field bed? number[] {x, y, z} mm: the printer's bed, checked when given
---@field voxel? number mm: measure walls and gaps on a distance grid of this voxel (default none: exact rays against the triangles)
---@field overhang? number degrees from vertical: faces tilted down past it overhang (45, in [1, 89])

---@class selfsim.PrintProblem
---@field severity "will fail"|"may fail"|"cosmetic"
---@field what string what and where
---@field fix string the change that fixes it, in the recipe's terms ("thicken to 0.8 mm (thickness = 0.8) ...")

---@class selfsim.PrintReport
---@field passes boolean
---@field summary string one line
---@field findings string[] one line each, for those that fail (will fail, may fail): "what: fix"
---@field problems selfsim.PrintProblem[] every finding, cosmetic ones too, the most serious first
---@field creases integer pairs of triangles where the surface touches itself (cosmetic)
---@field specks integer sealed pieces smaller than the nozzle's spot (cosmetic)
---@field overhang number mm² facing down past the `overhang` angle, off the bed (supports)
---@field first_layer number mm² it stands on: its cross-section half a layer above its lowest point
---@field reused boolean this call measured nothing: the solid's earlier check (its warning's, save's) was shared
---@field triangles integer
---@field size number[] {x, y, z} mm
---@field closed boolean a closed 2-manifold facing outwards
---@field crossing boolean whether it crosses itself (over more than the nozzle's width)
---@field thinnest_wall? number mm (nil when not measured)
---@field narrowest_gap? number mm (nil when not measured)
---@field wall_resolved? boolean false when the thinnest wall is finer than the grid resolves (thinnest_wall is then the bound it is under)
---@field gap_resolved? boolean false when the narrowest gap is finer than the grid resolves (narrowest_gap is then the bound it is under)
---@field thin? integer places under min_wall
---@field narrow? integer places under min_gap

-- Global functions ----------------------------------------------------------------------------------------

---The --set value of a parameter, read with the default's type (integer, number, boolean, string), or the
---default. The options annotate it: a range or choices that --set is checked against, a step, a doc line.
---@generic T: number|string|boolean
---@param name string
---@param default T
---@param options? selfsim.ParamOptions
---@return T
function param(name, default, options) end

---Records a named number for the run (results.json in the output folder); a sweep gathers every run's into
---results.csv and, when one number varies, plots each result against it. The name is letters, digits, '_',
---'-' and '.' (starting with a letter or '_'), and no parameter's; the value a finite number. Giving a
---name again with another value is an error. Returns the value.
---@param name string
---@param value number
---@return number
function result(name, value) end

---Writes a value into the output folder; the extension picks the format (.vtp .vtu .svg .eps .3mf .stl .obj
---.ply .vdb; .pvd and .vtp.series for a value's levels or a list; .csv for a table of rows).
---@param value selfsim.Curve|selfsim.Curve3|selfsim.Mesh|selfsim.Volume|table
---@param name string a file name relative to the output folder
---@param options? selfsim.SaveOptions
function save(value, name, options) end

---A Mesh or a Curve read from a file in the recipe's own folder (.vtp .vtu .stl .obj .ply .svg .vdb).
---@param name string relative, without '..'
---@return selfsim.Curve|selfsim.Curve3|selfsim.Mesh
function load(name) end

---An L-system grammar; draw it with g:curve{ level = n }. lsystem{...} makes one from selfsim's own syntax;
---lsystem.book reads the book's notation, lsystem.load cpfg's .l files.
---@class selfsim.lsystem
---@overload fun(options: selfsim.LsystemOptions): selfsim.Grammar
lsystem = {}

---A grammar written in the notation of The Algorithmic Beauty of Plants: ω : axiom, p1 : labels, → (or -->, ->),
---∧, #define NAME value, #ignore: symbols, conditions after ':', '*' for any, probabilities at the arrow
---(F →(0.33) ...), before it (F (0.33) → ...) or after the successor (: 0.33), n = 5 / derivation length: 5
---(the default level), δ = 25.7° (the angle). The table gives the other lsystem{} options (draw, seed, tropism).
---@param text string the book's text, one line each
---@param options? selfsim.LsystemOptions without axiom, rules, define, ignore, angle or level the text gives
---@return selfsim.Grammar
function lsystem.book(text, options) end

---A grammar from cpfg's L-system file (vlab's .l, the program of the book) in the recipe's folder: #define,
---#include "file.l" (beside it), /* comments */, Lsystem:, derivation length: (the default level), Axiom:,
---ignore: or consider:, productions with contexts, conditions and probabilities (: 0.3), homomorphism and
---decomposition sections (maximum depth:), endlsystem. cpfg's ?E queries, ~ surfaces, @ commands and C
---statements are refused by name. The table gives the other lsystem{} options (angle, draw, seed, tropism).
---@param name string relative to the recipe's folder, without '..', ending in .l
---@param options? selfsim.LsystemOptions without what the file gives
---@return selfsim.Grammar
function lsystem.load(name, options) end

---An open Curve through the points (at least 2); {x, y, z} points give a Curve3.
---@param points number[][]
---@return selfsim.Curve|selfsim.Curve3
function polyline(points) end

---A closed Curve through the points (at least 3; the first is repeated at the end); {x, y, z} give a Curve3.
---@param points number[][]
---@return selfsim.Curve|selfsim.Curve3
function polygon(points) end

---A Mesh from tables: a start surface or a region written in a recipe.
---@param options selfsim.MeshOptions
---@return selfsim.Mesh
function mesh(options) end

---Similarity path substitution (Hooper): each segment of path replaced by the generator, levels times.
---@param options selfsim.SubstituteOptions
---@return selfsim.Curve
function substitute(options) end

---Several curves as one value, each member keeping its number (cell field `curve`) and its own style.
---@param members (selfsim.Curve|selfsim.Curve3|selfsim.StyledMember)[]
---@return selfsim.Curve|selfsim.Curve3
function group(members) end

---One path walking each argument in turn (single-path curves or tables of {x, y}; 3D with 3D).
---@param ... selfsim.Curve|selfsim.Curve3|number[][]
---@return selfsim.Curve|selfsim.Curve3
function concat(...) end

---A uniform cubic B-spline from (0,0) to (1,0): smooth, approximating its control points (Kaplan).
---@param options selfsim.SplineOptions
---@return selfsim.Curve
function bspline(options) end

---A Catmull-Rom spline from (0,0) to (1,0), through its control points (Kaplan).
---@param options selfsim.SplineOptions
---@return selfsim.Curve
function catmull_rom(options) end

---Fewer points, every removed point within tolerance of the result (Ramer-Douglas-Peucker per path).
---@param curve selfsim.Curve|number[][]
---@param tolerance number
---@return selfsim.Curve
function simplify(curve, tolerance) end

---A developing fractal surface (Irving & Segerman): a curve's levels stacked at self-similar heights and
---joined into a smooth surface, optionally thickened into a solid.
---@param source selfsim.Grammar|selfsim.Curve[] a grammar, or a list of 2D curves, level 0 first
---@param options? selfsim.DevelopOptions
---@return selfsim.Mesh
function develop(source, options) end

---A curve's fractal dimension, by length scaling (exclusion curves) or box counting.
---@param curve selfsim.Curve|number[][]
---@param options? selfsim.DimensionOptions
---@return selfsim.Dimension
function dimension(curve, options) end

-- Global tables -------------------------------------------------------------------------------------------

---Smooth self-similar curves (Kaplan, Smooth Self-Similar Curves).
---@class selfsim.hoist
hoist = {}

---Q redrawn in P's frame: a point (x, y) of Q goes to P(x) + y N(x).
---@param Q selfsim.Curve|number[][] the path to redraw
---@param P selfsim.Curve|number[][] the base curve, from (0,0) to (1,0)
---@param options? selfsim.OntoOptions
---@return selfsim.Curve
function hoist.onto(Q, P, options) end

---m copies of C (from (0,0) to (1,0)) laid end to end and scaled by 1/m; m may be fractional.
---@param C selfsim.Curve|number[][]
---@param m number the multiplicity, 1 to 1e6
---@param options? selfsim.MultiplyOptions
---@return selfsim.Curve
function hoist.multiply(C, m, options) end

---The paper's ITERATE: each generation hoist.onto(hoist.multiply(C, m), P), always onto P.
---@param P selfsim.Curve|number[][] the base curve
---@param options selfsim.IterateOptions
---@return selfsim.Curve
function hoist.iterate(P, options) end

---The full control list from its first half, mirrored in x = 1/2.
---@param half number[][]
---@return number[][]
function hoist.mirror(half) end

---The full control list from its first half, turned half a circle about (1/2, 0).
---@param half number[][]
---@return number[][]
function hoist.rotate(half) end

---Exclusion-radius curves and surfaces (Bowyer, A new fractal curve).
---@class selfsim.exclusion
exclusion = {}

---An exclusion-radius curve filling a polygonal region, and its report (wrap the call in parentheses inside
---a table constructor to keep the curve only).
---@param options selfsim.ExclusionCurveOptions
---@return selfsim.Curve curve
---@return selfsim.ExclusionCurveReport report
function exclusion.curve(options) end

---Figure 4's exclusion discs around the points an exclusion curve made.
---@param curve selfsim.Curve|number[][]
---@param options selfsim.DiscsOptions
---@return selfsim.Curve
function exclusion.discs(curve, options) end

---An exclusion-radius surface grown inside a volume, and its report.
---@param options selfsim.ExclusionSurfaceOptions
---@return selfsim.Mesh surface
---@return selfsim.ExclusionSurfaceReport report
function exclusion.surface(options) end

---Regions of space for exclusion surfaces.
---@class selfsim.volume
volume = {}

---An axis-aligned box.
---@param options selfsim.BoxOptions
---@return selfsim.Volume
function volume.box(options) end

---A sphere (an icosphere within a quarter voxel of it).
---@param options selfsim.SphereOptions
---@return selfsim.Volume
function volume.sphere(options) end

---The inside of a closed mesh that does not cross itself: a Mesh, or a file in the recipe's folder.
---@param source selfsim.Mesh|string
---@param options? selfsim.VoxelOptions
---@return selfsim.Volume
function volume.mesh(source, options) end

---The inside of a level set saved by OpenVDB (a .vdb file in the recipe's folder).
---@param name string
---@param options? selfsim.VdbOptions
---@return selfsim.Volume
function volume.vdb(name, options) end

---The union of volumes, made on OpenVDB level sets.
---@param volumes selfsim.VolumeList
---@return selfsim.Volume
function volume.union(volumes) end

---The first volume less the others.
---@param volumes selfsim.VolumeList
---@return selfsim.Volume
function volume.difference(volumes) end

---Printable solids in millimetres and the print check.
---@class selfsim.solid
solid = {}

---An open surface as a closed solid of the given thickness (mm).
---@param mesh selfsim.Mesh
---@param options selfsim.ThickenOptions
---@return selfsim.Mesh
function solid.thicken(mesh, options) end

---A closed tube around every path of a 2D or 3D curve.
---@param curve selfsim.Curve|selfsim.Curve3
---@param options selfsim.TubeOptions
---@return selfsim.Mesh
function solid.tube(curve, options) end

---The even-odd region of closed 2D paths extruded to a height, optionally on a base plate.
---@param curve selfsim.Curve
---@param options selfsim.ReliefOptions
---@return selfsim.Mesh
function solid.relief(curve, options) end

---Loop subdivision of a mesh (as develop's), fields kept.
---@param mesh selfsim.Mesh
---@param options? selfsim.SmoothOptions
---@return selfsim.Mesh
function solid.smooth(mesh, options) end

---Fewer triangles, by VTK's quadric decimation; a closed mesh stays closed.
---@param mesh selfsim.Mesh
---@param options selfsim.DecimateOptions
---@return selfsim.Mesh
function solid.decimate(mesh, options) end

---The value scaled about the origin so its largest side is `size` mm (a number), or as the options say;
---prints the real size.
---@generic V: selfsim.Curve|selfsim.Curve3|selfsim.Mesh
---@param value V
---@param size number|selfsim.SizeOptions
---@return V
function solid.size(value, size) end

---The print check: closed, crossing, thinnest wall, narrowest gap, triangles, size; and the mesh marked
---with point and face fields `wall` and `gap` (mm).
---@param mesh selfsim.Mesh
---@param options? selfsim.CheckOptions
---@return selfsim.PrintReport report
---@return selfsim.Mesh marked
function solid.check(mesh, options) end

---@class selfsim.PlaceOptions
---@field centre? boolean centre the footprint (true); false only drops it to z = 0
---@field at? number[] {x, y}: where the footprint's centre goes ({0, 0})

---The mesh moved so its lowest point is at z = 0 and its footprint is centred on x = y = 0 (or `at`).
---@param mesh selfsim.Mesh
---@param options? selfsim.PlaceOptions
---@return selfsim.Mesh
function solid.place(mesh, options) end

---@class selfsim.UnionList
---@field [integer] selfsim.Mesh a closed solid
---@field voxel? number the grid's voxel when solids meet, mm (a quarter of the thinnest solid's box side, at most 0.2)
---@field check? selfsim.Check (true)

---One closed solid of every point of the listed solids: exact (joined as they are) when they do not meet,
---else on an OpenVDB grid; prints which unless -q. An open mesh is refused (solid.thicken it first).
---@param solids selfsim.UnionList
---@return selfsim.Mesh
function solid.union(solids) end

---The solid less the others: solid.difference(a, b) or solid.difference(a, { b, c, voxel = 0.1 }). A cut
---wholly inside `a` touching nothing is a sealed cavity (exact); cuts that meet `a` are made on a grid.
---@param solid selfsim.Mesh
---@param cuts selfsim.Mesh|selfsim.UnionList
---@return selfsim.Mesh
function solid.difference(solid, cuts) end

---@class selfsim.OrientOptions: selfsim.PlaceOptions
---@field face? "largest" lie on its largest flat face (the default)
---@field least? "overhang" turn to the least area overhanging past `overhang` degrees
---@field rotate? number or turn by these degrees about `axis`, as Mesh:transform
---@field axis? number[] {x, y, z} ({0, 0, 1})
---@field overhang? number degrees from vertical past which a face overhangs, 1 to 89 (45)
---@field nozzle? number mm (0.4): a pose must stand on a first layer of pi nozzle² (a flat face that large)

---The mesh turned to lie on its largest flat face (at least a first layer's: otherwise kept), to the least
---overhang among poses that stand, or by a given rotation, then placed on the bed (solid.place); prints
---what it did, what it stands on and the overhang before and after.
---@param mesh selfsim.Mesh
---@param options? selfsim.OrientOptions
---@return selfsim.Mesh
function solid.orient(mesh, options) end
