-- A nil global close to no name keeps Lua's own message (a short name is close to many: "foo" is not "os").
foo()
