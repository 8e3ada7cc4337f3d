require "modules.raises_table"
