-- args: --timeout 0.5
while true do end
