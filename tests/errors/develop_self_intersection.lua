-- develop: the unsmoothed dragon stack touches itself from level 4 on (its curves revisit points): refused,
-- naming the first two triangles that meet.
local curves = require "selfsim.curves"
develop(curves.dragon(), { levels = 6 })
