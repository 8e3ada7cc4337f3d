// The grammar fuzz target's input format: one field per line, "key value", so that libFuzzer's
// mutations (and the dictionary fuzz/grammar.dict) keep most inputs well formed and a finding reads
// like a recipe. Unknown lines are ignored; a later line overrides an earlier one.
//
//   axiom F+F--F+F        the axiom (raw bytes up to the end of the line)
//   rule F=F+F--F+F       a rule: the first byte is the symbol, the second a separator, the rest the
//                         replacement
//   angle 60              Grammar::angle (std::from_chars, so "inf", "nan", "1e308" are fine inputs)
//   turn +=120            Grammar::angles: symbol, separator, degrees
//   start 0 60            Grammar::start_angles (space separated; "start" alone gives an empty list)
//   shrink 0.5            Grammar::shrink
//   draw FG / move f      Grammar::draw / Grammar::move
//   level 4               TurtleOptions::level (default 3)
//   normalize 0           TurtleOptions::normalize (default 1)
//   budget 500            TurtleOptions::budget.limit, the --max-points (default and most 1e5)
#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "kernels/lsystem/grammar.h"

namespace selfsim::fuzz {

struct GrammarCase {
  lsystem::Grammar grammar;
  int level = 3;
  bool normalize = true;
  double budget = 1e5;
};

inline bool parse_number(std::string_view s, double& v) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  return std::from_chars(s.data(), s.data() + s.size(), v).ec == std::errc();
}

inline GrammarCase decode_grammar(std::string_view text) {
  GrammarCase c;
  while (!text.empty()) {
    const std::size_t eol = text.find('\n');
    std::string_view line = text.substr(0, eol);
    text = eol == std::string_view::npos ? std::string_view() : text.substr(eol + 1);
    const std::size_t space = line.find(' ');
    const std::string_view key = line.substr(0, space);
    const std::string_view value = space == std::string_view::npos ? std::string_view() : line.substr(space + 1);
    lsystem::Grammar& g = c.grammar;
    double v = 0;
    if (key == "axiom") {
      g.axiom = value;
    } else if (key == "rule" && !value.empty()) {
      g.rules[value[0]] = value.size() > 2 ? std::string(value.substr(2)) : std::string();
    } else if (key == "angle" && parse_number(value, v)) {
      g.angle = v;
    } else if (key == "turn" && value.size() > 2 && parse_number(value.substr(2), v)) {
      g.angles[value[0]] = v;
    } else if (key == "start") {
      g.start_angles.clear();
      std::string_view rest = value;
      while (!rest.empty()) {
        const std::size_t sp = rest.find(' ');
        if (parse_number(rest.substr(0, sp), v)) g.start_angles.push_back(v);
        rest = sp == std::string_view::npos ? std::string_view() : rest.substr(sp + 1);
      }
    } else if (key == "shrink" && parse_number(value, v)) {
      g.shrink = v;
    } else if (key == "draw") {
      g.draw = value;
    } else if (key == "move") {
      g.move = value;
    } else if (key == "level") {
      int level = 0;
      if (std::from_chars(value.data(), value.data() + value.size(), level).ec == std::errc()) c.level = level;
    } else if (key == "budget" && parse_number(value, v)) {
      if (v >= 1 && v <= 1e5) c.budget = std::floor(v);
    } else if (key == "normalize") {
      c.normalize = value != "0";
    }
  }
  return c;
}

}  // namespace selfsim::fuzz
