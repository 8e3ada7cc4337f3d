local g = lsystem { axiom = "A", rules = [[
A -> B[A]
B -> A B C
C < A > -> X
]] }
