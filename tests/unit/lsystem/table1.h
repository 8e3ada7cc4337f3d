// Seed 002 Table 1 grammars (and the single Koch curve) as test fixtures. scripts/selfsim/curves.lua holds
// the shipped copies; tests/lua/curves_test.lua checks those against the same closed forms.
#pragma once

#include <cmath>

#include "kernels/lsystem/grammar.h"

namespace table1 {

using selfsim::lsystem::Grammar;

inline Grammar dragon() {
  return {.axiom = "FX", .rules = {{'X', "X-YF"}, {'Y', "FX+Y"}}, .angle = 90, .shrink = std::sqrt(0.5)};
}
inline Grammar terdragon() { return {.axiom = "F", .rules = {{'F', "F-F+F"}}, .angle = 120}; }
inline Grammar hilbert() {
  return {.axiom = "+YF-XFX-FY+", .rules = {{'X', "+YF-XFX-FY+"}, {'Y', "-XF+YFY+FX-"}}, .angle = 90, .shrink = 0.5};
}
inline Grammar arrowhead() { return {.axiom = "XF", .rules = {{'X', "YF-XF-Y"}, {'Y', "XF+YF+X"}}, .angle = 60}; }
inline Grammar koch() { return {.axiom = "F", .rules = {{'F', "F+F--F+F"}}, .angle = 60}; }
inline Grammar koch_snowflake() {
  return {.axiom = "F++F++F", .rules = {{'F', "F-F++F-F"}}, .angle = 60, .shrink = 1.0 / 3};
}
inline Grammar gosper() {
  return {.axiom = "FX", .rules = {{'X', "X+YF++YF-FX--FXFX-YF+"}, {'Y', "-FX+YFYF++YF+FX--FX-Y"}}, .angle = 60};
}

}  // namespace table1
