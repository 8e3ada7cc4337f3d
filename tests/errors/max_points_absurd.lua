-- args: --max-points 1e30
-- exit: 2
print("not reached")
