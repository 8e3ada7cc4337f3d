// A recipe's parameter as param(name, default, { min, max, step, choices, doc }) declares it: what
// `--set` may give it, what `selfsim params` lists, the range a sweep is checked against and the control
// the studio draws.
#pragma once

#include <lua.hpp>
#include <optional>
#include <string>
#include <vector>

namespace selfsim::interp {

struct ParamSpec {
  enum class Type { integer, number, string, boolean };
  std::string name;
  Type type = Type::number;
  std::string default_text;  // the default as --set would give it: "11", "0.8", "clamp", "true"
  std::optional<double> min, max, step;
  std::vector<std::string> choices;
  std::string doc;
  std::string where;  // "recipe.lua:3: ", the line that declared it first

  bool operator==(const ParamSpec& o) const {
    return name == o.name && type == o.type && default_text == o.default_text && min == o.min && max == o.max &&
           step == o.step && choices == o.choices && doc == o.doc;
  }
};

const char* type_name(ParamSpec::Type type);

// The parameter declared by the call param(name, default, options) whose default is at `def` and options
// (nil or a table) at `opts`. Throws Error for an annotation that does not fit the default: min or max on a
// string, min above max, a default outside its range or not among its choices, a step that is not > 0.
ParamSpec read_param_spec(lua_State* L, const std::string& name, int def, int opts);

// Checks `text` (a --set value) against the parameter: its type (a whole number for an integer), range or
// choices; throws Error naming the parameter and what it expects. Sweeps and the studio check with this.
void check_param_value(const ParamSpec& spec, const std::string& text);

// Refuses (Error naming `set`, "k=1,01") two of a sweep's values that the parameter reads as one: for a
// number, the same number (1 and 01, 0 and -0); for an integer, the same integer (exact beyond 2^53). The
// sweep's list refuses repeated text; only the parameter knows when different text is the same value.
void check_distinct_values(const ParamSpec& spec, const std::string& set, const std::vector<std::string>& values);

// The one conversion of a --set value into the recipe's value: checked as above, then pushed with the
// parameter's type (an integer parameter always as a Lua integer).
void push_param_value(lua_State* L, const ParamSpec& spec, const std::string& text);

// The parameters as `selfsim params` prints them: a JSON array of objects, one per line.
std::string params_json(const std::vector<ParamSpec>& specs);

}  // namespace selfsim::interp
