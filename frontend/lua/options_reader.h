// Reads a Lua options table into C++ values, pbrt-style: every key a binding reads is recorded, and
// finish() rejects the rest with a suggestion ("unknown option 'multiplicty' (did you mean
// 'multiplicity'?)") so a typo is never silently ignored. Errors are thrown as selfsim::Error (not Lua
// errors) so they can pass through C++ frames; call_kernel turns them into recipe errors.
#pragma once

#include <lua.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "frontend/lua/lua_support.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::interp {

class Options {
 public:
  // Reads the table at `index`; nil or none gives an empty table. Throws Error if it is something else.
  Options(lua_State* L, int index);

  bool has(const char* key);
  double number(const char* key, double fallback);
  long long integer(const char* key, long long fallback, long long lo, long long hi);
  bool boolean(const char* key, bool fallback);
  std::string string(const char* key, const std::string& fallback);
  // Marks key as required: when it is absent, finish() says so (after naming any unknown key, which is
  // often the same option misspelt), with `hint` on what to pass. Returns whether it is present; readers
  // of an absent key return their fallback, so a binding reads on and calls finish() before using them.
  bool require(const char* key, const std::string& hint);
  // The index of the value in `names`, or fallback; an invalid value lists the valid ones.
  int enumeration(const char* key, const std::vector<std::string>& names, int fallback);
  // A list of finite numbers (empty when absent).
  std::vector<double> numbers(const char* key);
  // {x, y} / {x, y, z} points, and lists of them (empty when absent; counted against the point budget).
  std::optional<Vec2> point2(const char* key);
  std::optional<Vec3> point3(const char* key);
  std::vector<Vec2> points2(const char* key);
  std::vector<Vec3> points3(const char* key);
  // A Curve value, or a table of {x, y} points as one open path (empty when absent).
  Polyline curve(const char* key);
  // A Mesh value (null when absent).
  Held<Mesh> mesh(const char* key);
  // Accepts the keys 1..n as positional entries the caller reads itself (group{ a, b, stroke = ... }).
  void positional(lua_Integer n) { positional_ = n; }
  // Pushes the value at key (marking it read) and returns its Lua type; the caller pops it.
  int push(const char* key);
  // The keys no reader asked for, in sorted order.
  std::vector<std::string> unread();
  // Throws Error naming the first (in sorted order) key that no reader asked for, with the likeliest one
  // meant; then the first required key that is missing.
  void finish();

 private:
  lua_State* L;
  int index_;
  std::set<std::string> read_;
  lua_Integer positional_ = 0;
  std::vector<std::string> missing_;  // "option 'level' is required (...)", in the order required
};

// The string at index, checked to hold no NUL byte (which C++ would cut it at); `what` names it in errors.
std::string text_value(lua_State* L, int index, const std::string& what);

// A number read from the value on top of the stack, checked finite; `what` names it in errors.
double finite_number(lua_State* L, int index, const std::string& what);

// The index of `value` in `names`, or an Error: "invalid <what> 'x'<detail>, expected one of: 'a', 'b'".
int enum_index(const std::string& value, const std::vector<std::string>& names, const std::string& what,
               const std::string& detail = "");

// The closest of `candidates` to `word` by edit distance, if close enough to be a likely typo.
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace selfsim::interp
