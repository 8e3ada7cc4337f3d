// The closest name for a misspelt global or DSL function: Lua's "attempt to call a nil value (global
// 'lsytem')" becomes "attempt to call 'lsytem': did you mean 'lsystem'?", and "(field 'curv')" of a global
// table written `exclusion.curv` becomes "attempt to call 'exclusion.curv': did you mean 'exclusion.curve'?".
#pragma once

#include <lua.hpp>
#include <string>

namespace selfsim::interp {

// Called at the error site (in the message handler: level 1 is the function that raised). Returns the
// message with a suggestion, or `message` itself when it is no such error or no name is close. Only the
// text changes: the recipe failed either way. Never throws.
std::string with_nil_name_hint(lua_State* L, const std::string& message);

}  // namespace selfsim::interp
