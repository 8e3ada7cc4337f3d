-- The hint is given only where tropism is an option: elsewhere an unknown 'elasticity' is just unknown.
local c = exclusion.curve { elasticity = 0.2 }
