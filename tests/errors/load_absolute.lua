load("/etc/passwd.stl")
