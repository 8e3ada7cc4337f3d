// Which grammars are plants, and where a turtle's drawing goes (the one rule, docs/curves.md):
// a grammar that branches ('[' in its axiom or any successor, interpretation rules included) or draws in 3D
// is a plant. A plant keeps the turtle's own frame and units by default: it starts at the origin heading up
// (+y; start_angle 90 unless the grammar gives one) with steps of the turtle's length, times shrink^level.
// Any other open curve is normalised onto (0,0)-(1,0), as the papers draw them; a closed curve stays as
// drawn. TurtleOptions::normalize, when given, decides instead: true normalises an open plant as before
// (heading 0 unless given), false leaves any curve as drawn.
#pragma once

#include <string_view>

#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/turtle/turtle2d.h"

namespace selfsim::lsystem {

// The 3D turtle's turns (pitch & ^, roll \ /, and $), which make a grammar draw in 3D unless given another role.
inline constexpr std::string_view turns_3d = "&^\\/$";

// Whether g's axiom or a successor (productions, decomposition, interpretation; a byte grammar's text) writes
// `symbol`.
bool writes_symbol(const Grammar& g, char symbol);

// Whether g's axiom or a successor (productions, decomposition, interpretation) writes a '[' that pushes.
bool branches(const Grammar& g);

// Whether g's curve is 3D: g.dimension, or when 0 whether it writes a 3D turn (& ^ \ / $, unless given
// another role) or bends by tropism.
bool draws_in_3d(const Grammar& g);

bool is_plant(const Grammar& g);

// Whether an open curve of g drawn with opt is mapped onto (0,0)-(1,0).
bool normalizes(const Grammar& g, const TurtleOptions& opt);

// The turtle's start heading in degrees (counterclockwise from +x): the grammar's start_angle at the level
// when given; else 90 (up) for a plant kept in its own frame, 0 otherwise.
double start_heading(const Grammar& g, const TurtleOptions& opt);

}  // namespace selfsim::lsystem
