-- args: --threads 0
-- exit: 2
print(1)
