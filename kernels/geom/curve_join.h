// Joining curves into one value, and walking one backwards.
// - group: members side by side, every path kept, with a `curve` cell field numbering the members from 1,
//   so writers (per-member SVG style) and later kernels can tell them apart; a grid of variants or a plotter
//   sheet is one value and one file.
// - concat: single paths walked one after the other as one path (a point shared by the end of one and the
//   start of the next is kept once).
// - reversed: the same points walked from the end: paths in reverse order, each reversed.
// Fields follow join_fields (field.h); fields that joining would make wrong are dropped, and writers compute
// them again: `arclength` (concat, reversed) and the cell field `path` (group).
#pragma once

#include <span>

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim {

// Throws Error for no members or an empty member. `overrides` is empty or holds one set of uniform cell fields
// per member that replace the member's own (a style given to that member); `cell_defaults` (uniform) stand in
// for cell fields that only some members carry.
template <class V>
PolylineT<V> group(std::span<const PolylineT<V>* const> members, std::span<const Fields> overrides,
                   const Fields& cell_defaults, Progress& progress);

// Throws Error for no parts or a part that is not a single path (naming it, counted from 1).
template <class V>
PolylineT<V> concat(std::span<const PolylineT<V>* const> parts, Progress& progress);

template <class V>
PolylineT<V> reversed(const PolylineT<V>& c);

}  // namespace selfsim
