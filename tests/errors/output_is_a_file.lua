-- args: -o output_is_a_file.lua
-- exit: 2
print(1)
