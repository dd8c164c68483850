"""1989 addresses (UDEC manual (ICG1.5, 1989), Section 6.1 and Appendix B,
Problem E): the address lines of the printed direct-shear deck resolve to the
items the deck and its comments name, and a wrong address is refused with a
message naming it.

Problem E: 2 m x 2 m specimen cut at y = 1 by CRACK, zoned with GEN AUTO 2.1.
- HIST SDIS(159) ... : contact 159 is a contact of the joint y = 1
  (the deck monitors its shear and normal displacement);
- RSET 0.0 159 16: offset 16 = KCN, the normal displacement of contact 159;
- RSET 0.0 190 16: word IA(190 + 16) = IA(206) lies in the second joint
  contact's record (address 191) at offset 15 = KCS, as in the 1989 program
  (contact records are NVCN = 32 words: 159 + 32 = 191);
- BOUND COR=133,107: clockwise from 133 to 107 = the outer boundary of the
  bottom block ("FIX BOTTOM BLOCK"): 133 at (2,1) and 107 at (0,1) of the
  bottom block; BOUND COR=146,120 the top block's ("IMPOSE VELOCITY ON TOP
  BLOCK"): 146 at (0,1), 120 at (2,1) of the top block.
Also: the addresses survive SAVE / RESTART; HIST ADDRESS reads a field;
PFIX DOMAIN takes a domain address; wrong addresses and offsets are refused.
Problem G: its printed "domain 697" is not reproduced (the README says why);
the hole's own address from PRINT DOMAIN names it in PFIX DOMAIN, and 697
names the same domain by the compatibility table of the manual's decks
(with a note), in that model only.
"""
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir, write  # noqa: E402

udec = sys.argv[1]
folder = workdir()

SPECIMEN = """PROP MAT=1 D=2.60E-3 K=4000 G=3000
+ KN=10000 KS=10000 JKN=100000 JKS=100000 JEN=0.0 JES=0.0
+ JFRIC=0.577 JIF=1.035 JR=1.0E-4
ROUND 0.001
BLOCK 0,0 0,2 2,2 2,0
CRACK -0.1,1 2.1,1
CHANGE 0,100 0,100 FDEF MAT=1 CONS=1
GEN 0,100 0,100 AUTO 2.1
CHANGE JMAT=1 JCONS=3
INSITU STRESS 0, 0, -10
BOUND MAT=1
BOUND -0.1,2.1 -0.1,0.1 YVEL=0
BOUND -0.1,2.1 -0.1,2.1 STRESS 0, 0, -10
DAMP AUTO
FRAC 0.05 1.0
CYC 10
"""
ADDRESS_LINES = """HIST SDIS(159) NDIS(159) SSTR(159) NSTR(159)
HIST ADD(159,16)
RSET 0.0 159 16
RSET 0.0 190 16
PRINT CORNERS
PRINT CON
BOUND COR=133,107 XVEL=0 YVEL=0
BOUND COR=146,120 XVEL= -0.05
PRINT BOUND STATE
CYC 5
SAVE addr.sav
RESTART addr.sav
PRINT CORNERS
STOP
"""


def table(out, header):
    """Rows (lists of fields) of each table whose header starts with `header`."""
    tables, cur = [], None
    for line in out.splitlines():
        if line.strip().startswith(header):
            cur = []
            tables.append(cur)
            continue
        if cur is not None:
            f = line.split()
            if f and re.fullmatch(r"\d+", f[0]):
                cur.append(f)
            else:
                cur = None
    return tables


write(folder, "e.dat", SPECIMEN + ADDRESS_LINES)
rc, out = run(udec, ["e.dat"], cwd=folder, timeout=120)
check(rc == 0, "Problem E address lines run", out[-3000:])

# contact 159 and 191 are the joint's two end contacts, at y = 1
m = re.search(r"history \d+: SDIS 159: contact \(address 159, id (\d+)\) at \(([^,]+),([^)]+)\)", out)
check(m is not None, "SDIS(159) resolves to a contact", out[-3000:])
if m:
    check(abs(float(m.group(3)) - 1.0) < 1e-6, "contact 159 lies on the joint y = 1", m.group(0))
check(re.search(r"RSET: KCN \(offset 16\) := 0\S* in contact \(address 159,", out) is not None,
      "RSET 0.0 159 16 sets KCN of contact 159", out[-3000:])
m = re.search(r"RSET: KCS \(offset 15\) := 0\S* in contact \(address 191, id \d+\) at \(([^,]+),([^)]+)\)", out)
check(m is not None, "RSET 0.0 190 16 writes IA(206) = KCS of contact 191", out[-3000:])
if m:
    check(abs(float(m.group(2)) - 1.0) < 1e-6, "contact 191 lies on the joint y = 1", m.group(0))
check(re.search(r"history \d+: ADDRESS 159 16 = offset 16 of the contact \(address 159", out) is not None,
      "HIST ADD(159,16) names KCN of contact 159", out[-3000:])

corners = table(out, "CORNER   BLOCK")
check(len(corners) == 2, "two PRINT CORNERS tables", str(len(corners)))
if corners:
    by_addr = {int(r[-1]): r for r in corners[0]}
    # block of each corner: the bottom block has centroid y = 0.5 (PRINT BLOCK
    # is not needed: the bottom block's corners have y <= 1)
    bottom = {int(r[1]) for r in corners[0] if float(r[3]) < 0.5}
    want = {107: (0.0, 1.0, True), 120: (2.0, 1.0, False), 133: (2.0, 1.0, True),
            146: (0.0, 1.0, False)}
    for a, (x, y, is_bottom) in want.items():
        r = by_addr.get(a)
        check(r is not None, "corner address %d exists" % a, str(sorted(by_addr)))
        if r:
            ok = abs(float(r[2]) - x) < 1e-6 and abs(float(r[3]) - y) < 1e-6 and \
                (int(r[1]) in bottom) == is_bottom
            check(ok, "corner %d at (%g,%g) of the %s block" % (a, x, y, "bottom" if is_bottom else "top"),
                  " ".join(r))
    if len(corners) == 2:
        check(sorted(int(r[-1]) for r in corners[0]) == sorted(int(r[-1]) for r in corners[1]),
              "corner addresses survive SAVE / RESTART")
# PRINT BOUNDARY STATE: COR is our corner id, ADDRESS its 1989 address (the
# manual's note under BOUNDARY: "corner addresses ... are listed under the
# column heading COR"); both must name the same corner as PRINT CORNERS
state = table(out, "COR   BLOCK")
addr_of = {int(r[0]): int(r[-1]) for r in corners[0]} if corners else {}
check(len(state) == 1 and len(state[0]) == 8 and all(addr_of.get(int(r[0])) == int(r[-1])
                                                      for r in state[0]),
      "PRINT BOUNDARY STATE: ADDRESS column = the corner's address in PRINT CORNERS",
      str(state)[:1500])
check(any(int(r[-1]) == 133 for r in state[0]) if state else False,
      "PRINT BOUNDARY STATE lists corner address 133 (the deck's BOUND COR=133,107)")
sel = re.findall(r"BOUND COR=\S+ .*\nBOUNDARY: (\d+) of (\d+) boundary points", out)
# AUTO 2.1 leaves the 2 m edges whole (docs/zones.md): 8 boundary points
check(sel == [("4", "8"), ("4", "8")], "BOUND COR selects each block's 4 outer boundary points", str(sel))

# wrong addresses and offsets: refused, naming the address
for line, want in [("RSET 0.0 159 10", "RSET 159 10: offset 10 of the contact record at address 159"),
                   ("RSET 0.0 900000 1", "RSET 900000 1: address 900001 is in no record"),
                   ("BOUND COR=134,107 XVEL=0", "BOUNDARY CORNER 134: no corner has address 134"),
                   ("PFIX DOMAIN 697 PRES 1", "PFIX DOMAIN 697: no domain has address 697")]:
    write(folder, "w.dat", SPECIMEN + line + "\nSTOP\n")
    rc, out = run(udec, ["w.dat"], cwd=folder, timeout=120)
    check(rc != 0 and want in out, "refused with its address: " + line, out[-1500:])

# a history naming an address that is no contact's (a 1989 address not
# reproduced for the model, as Problem D's SDIS(3445)): not refused, since a
# history changes nothing; it records the contact whose record starts nearest
# (159: 160 is word 1 of its record) and a warning names the address, what
# its word is here and the contact taken (never silently)
write(folder, "w.dat", SPECIMEN + "HIST SDIS(160) ADD(161,16)\nSTOP\n")
rc, out = run(udec, ["w.dat"], cwd=folder, timeout=120)
check(rc == 0 and "Warning: HISTORY SDISPLACEMENT 160: no contact has address 160 here" in out
      and "word 160 is offset 1 of the contact record at 159" in out
      and re.search(r"recording the contact whose address is nearest: contact \(address 159, id \d+\)", out)
      and re.search(r"history \d+: SDIS 160: contact \(address 159,", out),
      "HIST SDIS(160): recorded at contact 159 with a warning naming 160", out[-1500:])
check("Warning: HISTORY ADDRESS 161 16: no record starts at address 161 here" in out
      and re.search(r"recording KCN \(offset 16\) of the record nearest to 161 among the kinds that keep "
                    r"that offset: contact \(address 159,", out) is not None,
      "HIST ADD(161,16): KCN of contact 159 with a warning naming 161", out[-1500:])

# a number that is an address and another corner's id: taken as the address,
# and the note says so (a user copying an id from COR is told). Corner ids are
# dense (model_compact): the specimen's 12 corners have no id 24, so the block
# is cut into six here (24 corners); the corner at (0,0) keeps address 24
AMBIGUOUS = """PROP MAT=1 D=2.60E-3 K=4000 G=3000 JKN=100000 JKS=100000 JFRIC=0.577
ROUND 0.001
BLOCK 0,0 0,2 2,2 2,0
CRACK -0.1,1 2.1,1
CRACK -0.1,0.5 2.1,0.5
CRACK 1,-0.1 1,2.1
BOUND -0.1,2.1 -0.1,0.1 YVEL=0
"""
write(folder, "amb.dat", AMBIGUOUS + "BOUND COR=24,37 XVEL=0\nSTOP\n")
rc, out = run(udec, ["amb.dat"], cwd=folder, timeout=120)
check(rc == 0 and re.search(r"note: BOUNDARY CORNER 24: taken as an address, the corner \(address 24, id "
                            r"(\d|1\d|2[0-35-9])\) at \(0\.00000,0\.00000\)", out) is not None
      and "corner id 24 is another one" in out, "an address that is also an id: the note names both",
      out[-1500:])

# PFIX DOMAIN by address: the joint's interior domain
write(folder, "d.dat", SPECIMEN + "PRINT DOMAIN\nSTOP\n")
rc, out = run(udec, ["d.dat"], cwd=folder, timeout=120)
doms = [r for t in table(out, "DOMAIN          AREA") for r in t]
inner = [r for r in doms if r[3] == "F"]
check(len(inner) >= 1, "an inner domain is listed with its address", out[-1500:])
if inner:
    a = inner[0][4]
    write(folder, "p.dat", SPECIMEN + "FLUID 0.001 0.0\nPFIX DOMAIN %s PRES 1\nSTOP\n" % a)
    rc, out = run(udec, ["p.dat"], cwd=folder, timeout=120)
    check(rc == 0 and "PFIX: pressure fixed in 1 domains" in out, "PFIX DOMAIN %s by address" % a,
          out[-1500:])
# Problem G: the printed "domain 697" (the hole) is not reproduced (the
# hole's record is at another address, examples/application/G/README.md);
# the hole's own address, from PRINT DOMAIN, names it in PFIX DOMAIN, and the
# printed 697 resolves to the same domain by the compatibility table of the
# manual's decks (model_address_compat: Problem G's outline 0..10 x 0..10,
# the domain centred at the hole's centre (5,5)), with a note naming 697, the
# manual's words and the domain taken. In another model (the same deck on a
# 12 m wide square, or the specimen above) 697 is refused as before.
GDECK = """round 0.01
block 0 0 0 10 10 10 10 0
crack 0 5 10 5
crack 5 0 5 10
tunnel 5 5 0.6 12
jset 0 0 10 0 0 0 2 0
jset 90 0 10 0 0 0 2 0
gen auto 1.25
prop m 1 k 1e10 g 3e9 d 3000
prop m 1 jkn 1e10 jks 1e10 jfric 1 jperm 1e8 azero 0.0001 ares 0.00005
delete 4.5 5.5 4.5 5.5
print domain
"""
write(folder, "g.dat", GDECK + "stop\n")
rc, out = run(udec, ["g.dat"], cwd=folder, timeout=120)
doms = [r for t in table(out, "DOMAIN          AREA") for r in t if len(r) >= 5 and r[3] in "TF"]
hole = [r for r in doms if abs(float(r[1]) - 1.086) < 0.01]
check(rc == 0 and len(hole) == 1, "Problem G: one domain of the hole's area (1.086 m^2)", out[-2000:])
check(not any(r[4] == "697" for r in doms), "Problem G: no domain has address 697 in this layout",
      str(doms)[:1500])
if hole:
    a = hole[0][4]
    write(folder, "g2.dat", GDECK + "fluid den=1000 bul=2e9 coh .1\npfix dom %s pres .2e4\n"
          "pfix dom 697 pres .2e4\nstop\n" % a)
    rc, out = run(udec, ["g2.dat"], cwd=folder, timeout=120)
    check(rc == 0 and out.count("PFIX: pressure fixed in 1 domains") == 2,
          "Problem G: PFIX DOMAIN %s (the hole) by address, and the printed 697" % a, out[-2000:])
    check(re.search(r"note: PFIX DOMAIN 697: 1989 address of the domain of Appendix B Problem G.*"
                    r"compatibility table.*: domain \(address %s, id %s\)" % (a, hole[0][0]), out)
          is not None, "Problem G: 697 resolves to the hole's domain, with a note naming both",
          out[-2000:])
wide = GDECK.replace("block 0 0 0 10 10 10 10 0", "block 0 0 0 10 12 10 12 0")
write(folder, "g3.dat", wide + "fluid den=1000 bul=2e9 coh .1\npfix dom 697 pres .2e4\nstop\n")
rc, out = run(udec, ["g3.dat"], cwd=folder, timeout=120)
check(rc != 0 and "PFIX DOMAIN 697: no domain has address 697" in out,
      "Problem G's 697 in a model of another outline is refused, naming it", out[-1500:])
finish()
