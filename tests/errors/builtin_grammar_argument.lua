local c = (require "selfsim.curves").dragon(12)
