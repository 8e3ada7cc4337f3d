-- args: --seed 18446744073709551616
-- exit: 2
print("not reached")
