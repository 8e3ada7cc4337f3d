require "selfsim\0.curves"
