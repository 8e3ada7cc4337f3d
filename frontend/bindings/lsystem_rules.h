// Reads an lsystem{}'s rules in every form a recipe may write them, and decides whether the grammar is
// plain (the byte kernel) or a module grammar (parameters, conditions, contexts, weighted choices):
//   rules = { F = "F+F-F" }                                 plain, keyed by symbol
//   rules = { F = { { 1, "F[+F]F" }, { 2, "F[-F]F" } } }    weighted choices
//   rules = { ["A<B>C"] = "X", ["A(x) : x > 1"] = "F(x)" }  a key may carry context, parameters, a condition
//   rules = { "A(x) : x > 1 -> F(x) [+(30) A(x*0.6)]" }     a list of ABOP rule strings (tried in order)
//   rules = [[ ... one ABOP rule per line ... ]]            a block of them
#pragma once

#include <lua.hpp>

#include "kernels/lsystem/grammar.h"

namespace selfsim::interp {

// Reads the rules value at `index` and g.axiom (already set) into g: g.rules for a plain grammar, else
// g.start and g.productions. Throws Error naming the rule, with the rule and a caret under the column on
// the lines after the message.
void read_rules(lua_State* L, int index, lsystem::Grammar& g);
// Rules of another set (decomposition, interpretation: option `name`) in the same forms, always as
// productions.
std::vector<lsystem::Production> read_rule_set(lua_State* L, int index, const lsystem::Grammar& g, const char* name);
// Makes a plain grammar a module grammar (its rules as productions, its axiom as modules), for the module
// turtle: 3D, line widths and colours, polygons.
void to_modules(lsystem::Grammar& g);

}  // namespace selfsim::interp
