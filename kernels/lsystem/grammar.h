// An L-system grammar with its turtle interpretation (seed 002 §1 and Table 1; seed 001).
// Symbols are single bytes. '+' turns left (counterclockwise) by `angle`, '-' turns right, '|' turns
// around, '[' and ']' push and pop the turtle; per-symbol angles override these turns and may give any
// symbol a turn. Symbols in `draw` step forward drawing, those in `move` step without drawing; every other
// symbol only takes part in rewriting.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "kernels/geom/vec3.h"
#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

struct Grammar {
  std::string axiom;                  // level 0; must not be empty
  std::map<char, std::string> rules;  // symbol -> replacement; symbols without a rule stay as they are
  double angle = 90;                  // degrees turned by '+' (left) and '-' (right)
  std::map<char, double> angles;      // degrees turned by a symbol, positive = left; overrides angle
  // Initial heading in degrees, cycled by level (level % size); none given: the turtle's default, 90 (up)
  // for a plant kept in its own frame and 0 otherwise (turtle/plant.h).
  std::vector<double> start_angles;
  double shrink = 1;        // step length is shrink^level (used when a curve is not normalised)
  std::string draw = "FG";  // symbols that step forward drawing a segment
  std::string move = "f";   // symbols that step forward without drawing

  // Module grammars (production.h): rules with parameters, conditions, contexts or weighted choices.
  // For them `start` holds the axiom parsed as modules and `productions` the rules, in order; `rules`
  // stays empty, and module_rewrite.h derives the levels instead of rewrite.h.
  std::vector<Call> start;
  std::vector<Production> productions;
  std::vector<std::pair<std::string, double>> constants;  // names every expression may read (option 'define')
  // Applied to every module a step writes (and to the axiom's), recursively: a module's parts (L-Py's
  // decomposition). Context-free.
  std::vector<Production> decomposition;
  // Applied only when drawing, recursively: what a module looks like (ABOP's homomorphism, L-Py's
  // interpretation). Context-free.
  std::vector<Production> interpretation;
  int max_depth = 8;                 // how deep decomposition and interpretation recurse, in [0, max_rule_depth]
  std::string ignore = "+-&^\\/|$";  // symbols a context skips over (the turtle's turns)
  std::uint64_t seed = 0;            // stochastic choices follow from it
  int dimension = 0;                 // the turtle's: 2, 3, or 0 to choose by the symbols (module_turtle.h)
  Vec3 tropism{};                    // 3D: the heading bends toward it after each step (turtle_frame3.h)
  int level = -1;                    // the level g:curve() and g:string() draw when given none (-1: none)

  bool modules() const { return !start.empty(); }
  bool stochastic() const;
  // Throws selfsim::Error naming the first bad field.
  void validate() const;
  // Degrees turned by symbol c, or 0 if c does not turn.
  double turn_of(char c) const;
  bool draws(char c) const { return draw.find(c) != std::string::npos; }
  bool moves(char c) const { return move.find(c) != std::string::npos; }
  // The given start angle at a level, 0 when none is given (turtle/plant.h's start_heading() is the turtle's).
  double start_angle(int level) const {
    return start_angles.empty() ? 0 : start_angles[static_cast<std::size_t>(level) % start_angles.size()];
  }
};

// Deepest decomposition or interpretation (option 'max_depth').
constexpr int max_rule_depth = 64;
// Most constants a grammar may define (option 'define').
constexpr std::size_t max_constants = 32;
// Highest level any kernel accepts: depth-first expansion keeps one frame per level.
constexpr int max_level = 256;
// Most symbols the axiom and all rules may hold together (a megabyte of grammar).
constexpr double max_grammar_symbols = 1 << 20;

}  // namespace selfsim::lsystem
