local curves = require "selfsim.curve"
