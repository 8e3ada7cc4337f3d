-- Every value type's methods check what they take: a Volume's too.
local v = volume.sphere { center = { 0, 0, 0 }, radius = 1 }
print(v:bbox("tight"))
