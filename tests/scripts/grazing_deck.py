"""The lead's random tunnel deck, seed 234 (session 39): a 20 m square cut
by two joint sets, one joint of the first 2.163 m from the centre of a
ring of radius 2.201 m (24 sides, apothem 2.182 m), ROUND 0.02. Shared by
e2e.tunnel_grazing (the ring cut by TUNNEL) and e2e.arc_openings (by ARC
360); `opening` is the command that cuts the ring."""


def grazing_deck(opening):
    return f"""round 0.02
block 0,0 0,20 20,20 20,0
jset 76.20,0 40,0 0,0 2.353,0 (9.568,9.036)
jset 149.11,5 6.331,1.266 1.834,0.367 3.373,0.337 (10.000,10.000)
{opening}
gen auto 2.500
prop mat=1 d=2600 k=2e+10 g=1.2e+10
prop jmat=1 jkn=5e+09 jks=1e+09 jfric=0.632 jcoh=0
bound stress -1.367e+07 2.068e+06 -1.73e+07
insitu stress -1.367e+07 2.068e+06 -1.73e+07
damp auto
solve
delete ann 10.0,10.0 0 2.2011
solve cycles 40000
stop
"""
