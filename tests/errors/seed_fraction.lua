-- args: --seed 1.5
-- exit: 2
print("not reached")
