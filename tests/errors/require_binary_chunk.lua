require "modules.binary"
