-- an L-system curve's `level` is the level it was drawn at, not the level each point was made at
local curves = require "selfsim.curves"
local d = dimension(curves.dragon():curve(8))
