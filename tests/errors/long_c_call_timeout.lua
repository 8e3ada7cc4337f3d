-- args: --timeout 0.3
print(("a"):rep(3e5):find(".-b"))
