"""A 2 x 1 rigid block on a joint, cut out of one BLOCK by CRACKs with the
pieces beside it DELETEd (the lower block spans x -1 .. 3, y -1 .. 0; FIX it
with FIX -2 4 -1 0). Shared by e2e.camp8_decks (the direct shear test) and
e2e.camp9_decks (a bolt across the joint)."""

SHEAR_BOX = """ROUND 0.01
BLOCK -1,-1 -1,1 3,1 3,-1
CRACK -1,0 3,0
CRACK 0,-0.5 0,1.5
CRACK 2,-0.5 2,1.5
DELETE -1 0 0 1
DELETE 2 3 0 1
"""
