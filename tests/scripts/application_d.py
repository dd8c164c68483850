"""Application Problem D (gravity dam on a jointed foundation: flow, then
earthquake; UDEC manual (ICG1.5, 1989), Appendix B, Problem D): the three
printed stages run in order, stage 3 with the free field (FFIELD, BOUNDARY
FF; Section 3.8.2), and its results against what the manual states.

The decks run as printed. Their HIST SDIS(3445) ... and HIST ADD(3445,21),
ADD(4358,4) name a contact and a domain by 1989 address, a numbering udec
does not reproduce for this model (examples/application/D/README.md says
why, measured). The compatibility table of the manual's decks
(src/model/model_address_compat.f90) resolves them to the items the manual
identifies, with a note naming the printed address, the manual's words and
the entity taken. The harness adds PRINT HIS 3 4 5 6 and PRINT DOMAIN after
stage 2's SAVE, and PRINT HIS 3 5 6 before stage 3's STOP (it reads them;
nothing else is changed).

Checks (the manual's statements, Appendix B Problem D, Figs. D-1 to D-9):
* every stage ends with exit status 0 and no "not yet implemented" from
  FFIELD or BOUNDARY FF;
* 3445 resolves, in stages 2 and 3, with a note for each of its six history
  requests, to one contact within 0.2 m of the deck comment's "x=-33.42
  y=-30.47" (Fig. D-1 marks it); 4358 to a domain whose centre is within
  1 m of the comment's "x=-22,-26" and whose contacts include that one
  (Fig. D-5: "Domain 4358 Next to Contact 3445");
* Fig. D-4, "joint opening (indicated by positive normal displacement)":
  NDIS(3445) > 0 at the end of stage 2;
* Fig. D-5, "steady state conditions have been achieved": the pressure of
  domain 4358 over the last tenth of stage 2 within 1e-4 of its final
  value (relative), and so the flow rate through contact 3445 (KCQ, offset
  21); the final pressure lies between the hydrostatic pressures of the
  two boundary heads at the domain's depth (steady flow's maximum
  principle: the head inside lies between the boundary heads, 0 downstream
  and 0.980 / (rho g) upstream, rho g = 0.001 x 9.81 MPa/m);
* "a vertical propagating sinusoidal shear wave (Freq = 5 Hz) is applied
  for 1.5 seconds": stage 3's CYCLE 1000 at MSCALE PART 1.5E-3 ends at
  t = 1.5 s (the step is tdel, manual Section 4.5 MSCALE PART; relative
  tolerance 1e-4);
* "the large amount of slip along the first joint at 20 degrees": the
  largest shear displacement of the contacts PRINTed by the deck (range
  -50,55 -35,2) is on the 20-degree joint (contact normal at 110 or -70
  degrees), and contact 3445 is on that joint;
* "The joint upstream at 70 degrees is open (i.e., no effective stress)":
  every contact of the -70-degree joint upstream of the dam (normal at 20
  or -160 degrees, x < -30) carries no normal force;
* Fig. D-7, "accumulation of horizontal displacement with each load
  cycle": the mean crest x-displacement over the last load cycle (0.2 s)
  exceeds that over the first by more than 50 %;
* Fig. D-9, "again showing accumulation of joint shear displacement" (its
  caption says contact 3353, the deck 3445): the shear displacement of
  contact 3445 in stage 3 grows in magnitude from each load cycle (0.2 s)
  to the next after the first, and to more than five times its stage-2
  value by the end.
* convergence in the time step: stage 3 again at half the step (MSCALE
  PART 0.75E-3, CYCLE 2000) gives the same largest slip, at the same
  contact, within 5 % (measured -1.7 %; -34 % when INSITU's zoned-joint
  balance left inadmissible joint forces, examples/application/D/README.md).
* the slip's size against Newmark's sliding block (the reference we can
  defend; the comment above newmark() gives it and its tolerance): the
  rigid-plastic wedge above the first 20-degree joint, in limit equilibrium
  with stage 2's water pressures and driven by the rock under the joint,
  slips within the range the model's wedge slips along its base in stage 3
  (measured: Newmark 0.0541 m, the base 0.0395 to 0.0574 m).
The manual's slip of 0.07 m (Fig. D-6) is printed, not asserted: measured
0.0580 m (-17 %), converged in the step (-1.7 %) and in the zoning (+4.5 %
at a third of the zone size, the step scaled with it), between the two
readings of DAMP ... MASS the manual leaves open (0.058 / 0.083 m), so no
tolerance around 0.07 m can be defended (README, "The slip of Fig. D-6").
"""
import math
import os
import re
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, header_rows, run, workdir  # noqa: E402

udec, source = sys.argv[1], sys.argv[2]
src = os.path.join(source, "examples", "application", "D")
d = workdir()
decks = {n: open(os.path.join(src, n)).read()
         for n in ("D1_gravity.dat", "D2_reservoir_flow.dat", "D3_dynamic.dat")}


def stage(name, text):
    with open(os.path.join(d, name), "w") as f:
        f.write(text)
    rc, out = run(udec, [name], cwd=d, timeout=300)
    check(rc == 0, f"{name} runs to its end", out[-2500:])
    bad = [l for l in out.splitlines() if "not yet implemented" in l
           and ("FFIELD" in l or "BOUNDARY" in l)]
    check(not bad, f"{name}: FFIELD and BOUNDARY FF are implemented", "\n".join(bad))
    return out


def contacts_table(out, after):
    """Rows of the first contact table after the line `after`: id -> fields."""
    lines = out.splitlines()
    i = next(k for k, l in enumerate(lines) if l.strip() == after)
    tabs, cur, hdr = [], None, None
    for l in lines[i + 1:]:
        f = l.split()
        if f[:1] == ["CONTACT"]:
            hdr, cur = f, {}
            tabs.append((hdr, cur))
            continue
        if hdr and len(f) == len(hdr) and f[0].isdigit():
            cur[int(f[0])] = dict(zip(hdr, f))
            continue
        if hdr:
            break
    return tabs




def address_notes(out, printed):
    """(command, kind, id, x, y) of the compatibility notes for 1989 address `printed`."""
    return re.findall(r"note: (HISTORY \S+) %d: 1989 address of the (contact|domain) of Appendix B "
                      r"Problem D.*compatibility table.*: \2 \(address \d+, id (\d+)\) at "
                      r"\(([^,]+),([^)]+)\)" % printed, out)


def history(out, n, last=False):
    """(time, value) rows of the (last, if `last`) PRINT HIS n in `out`."""
    lines = out.splitlines()
    ks = [i for i, l in enumerate(lines) if l.strip() == f"PRINT HIS {n}"]
    rows = []
    for l in lines[(ks[-1] if last else ks[0]) + 2:] if ks else []:
        f = l.split()
        if len(f) != 2:
            break
        rows.append((float(f[0]), float(f[1])))
    return rows


out1 = stage("D1.dat", decks["D1_gravity.dat"])

d2 = decks["D2_reservoir_flow.dat"]
check("HIST SDIS(3445) NDIS(3445)" in d2 and "HIST ADD(4358,4)" in d2,
      "stage 2 as printed names contact 3445 and domain 4358 by 1989 address")
out2 = stage("D2.dat", d2.replace("\nSTOP", "\nPRINT HIS 3\nPRINT HIS 4\nPRINT HIS 5\nPRINT HIS 6\n"
                                  "PRINT DOMAIN\nSTOP"))
n = address_notes(out2, 3445)
print("\n".join(l for l in out2.splitlines() if l.startswith("note: HISTORY")))
check([c for c, *_ in n] == ["HISTORY SDISPLACEMENT", "HISTORY NDISPLACEMENT", "HISTORY ADDRESS"]
      and len({r[2] for r in n}) == 1,
      "stage 2: SDIS(3445), NDIS(3445), ADD(3445,21) each note the one contact taken", str(n))
con = int(n[0][2]) if n else None
if n:
    x, y = float(n[0][3]), float(n[0][4])
    check(((x + 33.42) ** 2 + (y + 30.47) ** 2) ** 0.5 < 0.2,
          "3445 is the contact the deck comment places at x=-33.42 y=-30.47", f"{x} {y}")
m = address_notes(out2, 4358)
check(len(m) == 1 and m[0][1] == "domain", "stage 2: ADD(4358,4) notes the domain taken", str(m))
if m:
    dom, x, y = m[0][2], float(m[0][3]), float(m[0][4])
    check(((x + 22.0) ** 2 + (y + 26.0) ** 2) ** 0.5 < 1.0,
          "4358 is the domain at the deck comment's x=-22,-26", f"{x} {y}")
    lines = out2.splitlines()
    k = max(i for i, l in enumerate(lines) if l.strip() == "PRINT DOMAIN")
    ring, cur = {}, None
    for l in lines[k + 2:]:
        f = l.split()
        if len(f) >= 5 and f[3] in ("T", "F"):
            cur = f[0]
            ring[cur] = f[5:]
        elif cur and f and all(t.isdigit() for t in f):
            ring[cur] += f
        else:
            break
    ring = [int(c) for c in ring.get(dom, [])]
    check(con in ring, "domain 4358 is next to contact 3445 (Fig. D-5; PRINT DOMAIN's contacts)",
          f"domain {dom}: {ring}, contact {con}")
nd = history(out2, 4)
check(len(nd) > 10 and nd[-1][1] > 0.0,
      "Fig. D-4: joint 3445 opens (positive normal displacement) by the end of stage 2",
      str(nd[-3:]))
for h, what in ((6, "the pressure of domain 4358"), (5, "the flow rate through contact 3445")):
    r = history(out2, h)
    tail = r[int(0.9 * len(r)):]
    fin = r[-1][1] if r else 0.0
    print(f"stage 2: {what}: {fin:.6g} at t = {r[-1][0] if r else 0:.4g}")
    check(len(r) > 10 and fin != 0.0 and all(abs(v - fin) <= 1e-4 * abs(fin) for _, v in tail),
          f"Fig. D-5: {what} is steady over the last tenth of stage 2", str(tail))
p = history(out2, 6)
if p and m:
    rg, depth = 0.001 * 9.81, -float(m[0][4])
    lo, hi = rg * depth, 0.980 + rg * depth
    print(f"domain 4358 pressure {p[-1][1]:.5g} MPa, between the boundary heads' {lo:.4g} and {hi:.4g}")
    check(lo < p[-1][1] < hi, "the steady pressure lies between the boundary heads' hydrostatic "
          "pressures at the domain's depth", f"{p[-1][1]} not in ({lo}, {hi})")

d3 = decks["D3_dynamic.dat"].replace("\nSTOP", "\nPRINT HIS 3\nPRINT HIS 5\nPRINT HIS 6\nSTOP")
out3 = stage("D3.dat", d3)
# MSCALE PART 1.5E-3 raises the masses of the gridpoints too light for that
# step; each CYCLE says how many and by how much (a finer zoning at the printed
# step raised some 50-fold and changed the slip silently, docs/zones.md)
MSC = r"note: MSCALE PART raised the masses of (\d+) of (\d+) gridpoints, at most ([\d.]+)-fold"
msc3 = re.findall(MSC, out3)
check(len(msc3) == 1 and int(msc3[0][0]) > 0 and float(msc3[0][2]) > 1.0,
      "stage 3 says how many gridpoint masses MSCALE PART raised, once", str(msc3))
n3 = address_notes(out3, 3445)
check([c for c, *_ in n3] == ["HISTORY SDISPLACEMENT", "HISTORY NDISPLACEMENT", "HISTORY SSTR",
                              "HISTORY SRAT"] and {int(r[2]) for r in n3} == {con},
      "stage 3: SDIS, NDIS, SSTR, SRAT(3445) each note the same contact as stage 2", str(n3))
m = re.findall(r"cycle (\d+), time\s+([^,\s]+), timestep\s+([^,\s]+)", out3)
check(len(m) > 0, "stage 3 cycles")
if m:
    t, dt = float(m[-1][1]), float(m[-1][2])
    print(f"stage 3: ends at t = {t:.6g} s, step {dt:.6g} s")
    check(abs(t - 1.5) < 1.5e-4, "stage 3 covers the 1.5 s of loading the text gives", f"{t}")
    check(abs(dt - 1.5e-3) < 1.5e-7, "stage 3's step is MSCALE PART's tdel 1.5E-3", f"{dt}")

sd = history(out3, 5)
at = []
for k in range(1, 8):
    before = [v for t, v in sd if t <= 0.2 * k + 1e-9]
    if before:
        at.append(abs(before[-1]))
print("Fig. D-9: |shear displacement| of contact 3445 at the end of each 0.2 s load cycle: "
      + " ".join(f"{v:.4g}" for v in at) + (f", {abs(sd[-1][1]):.4g} m at 1.5 s" if sd else ""))
check(len(at) == 7 and all(b > a for a, b in zip(at[1:], at[2:]))
      and abs(sd[-1][1]) > 5 * abs(sd[0][1]),
      "Fig. D-9: joint shear displacement at contact 3445 accumulates with each load cycle", str(at))

tabs = contacts_table(out3, "PRINT -50,55 -35,2 CON")
if len(tabs) >= 3:
    g, disp, force = tabs[0][1], tabs[1][1], tabs[2][1]
    slip = {c: abs(float(disp[c]["SHEAR-DISP"])) for c in disp}
    top = max(slip, key=slip.get)
    print(f"largest slip {slip[top]:.4f} m at contact {top} (normal angle {g[top]['ANGLE']}), "
          "manual (Fig. D-6): 0.07 m along the first joint at 20 degrees")
    check(float(g[top]["ANGLE"]) in (110.0, -70.0),
          "the largest slip is on the 20-degree joint", str(g[top]))
    check(con in g and float(g[con]["ANGLE"]) in (110.0, -70.0),
          "contact 3445 is on the 20-degree joint", str(g.get(con)))
    up = [c for c in g if float(g[c]["ANGLE"]) in (20.0, -160.0) and float(g[c]["X"]) < -30.0]
    check(len(up) > 0, "the upstream 70-degree joint is in the printed range")
    fn = [float(force[c]["NORMAL-FORCE"]) for c in up if c in force]
    print(f"upstream 70-degree joint: contacts {up}, normal forces {fn}")
    check(len(fn) == len(up) and all(f == 0.0 for f in fn),
          "the upstream 70-degree joint is open (no normal force)", str(fn))
    # Convergence in the time step: stage 3 again from DAM2 with half the
    # step (MSCALE PART 0.75E-3, CYCLE 2000: the same 1.5 s). An explicit
    # scheme's slip changes little when its step halves: within 5 %
    # (measured 1.3 % before merge e619229; -34 % after it, when INSITU's
    # zoned-joint balance left 10 kN of tension on cohesionless joints,
    # fixed since).
    dh = d3.replace("MSCALE PART 1.5E-3", "MSCALE PART 0.75E-3").replace("CYCLE 1000", "CYCLE 2000")
    check(dh.count("0.75E-3") == 1 and "CYCLE 2000" in dh, "stage 3 at half the step: deck edited")
    outh = stage("D3h.dat", dh)
    th = contacts_table(outh, "PRINT -50,55 -35,2 CON")
    msch = re.findall(MSC, outh)
    check(len(msch) == 1 and msc3 and int(msch[0][0]) < int(msc3[0][0])
          and float(msch[0][2]) < float(msc3[0][2]),
          "half the MSCALE PART step raises fewer masses, by less", f"{msc3} {msch}")
    if len(th) >= 2:
        sh = {c: abs(float(th[1][1][c]["SHEAR-DISP"])) for c in th[1][1]}
        toph = max(sh, key=sh.get)
        print(f"half the step: largest slip {sh[toph]:.4f} m at contact {toph} "
              f"({(sh[toph] / slip[top] - 1) * 100:+.1f} %)")
        check(toph == top and abs(sh[toph] - slip[top]) <= 0.05 * slip[top],
              "stage 3's largest slip converges in the time step (half the step: within 5 %)",
              f"{slip[top]} at {top}, {sh[toph]} at {toph}")
    else:
        check(False, "stage 3 at half the step prints its contact tables", str(len(th)))
else:
    check(False, "stage 3 prints its contact tables", str(len(tabs)))

# Newmark's sliding block (independent estimate of the slip of Fig. D-6).
# The wedge above the first 20-degree joint (the JSET through (50, 0)) is
# cut off upstream by the -70-degree joint that the manual and our run show
# open (the JSET through (-50.99, 16.45)); it carries the dam. Limit
# equilibrium of that rigid wedge (dam and rock: weight, buoyancy below the
# water table y = 0, the reservoir's 0.5 gamma_w h^2 on the dam face and
# 0.980 MPa on the rock between the joint and the dam, and the water
# pressures of stage 2's domains on the two joints) with friction 0.577 and
# no cohesion (MAT 1) gives its static state; Newmark's rigid-plastic block
# (Newmark 1965) then integrates the sliding along the joint (both ways)
# driven by the rock under the joint: the velocity of its gridpoint on the
# joint at (0, -18.2), recorded every cycle in a second run of stage 3, and
# the deck's mass damping (alpha = 2 x 0.10 x 2 pi 2 s^-1 on absolute
# velocity). Reference and tolerance: the slip of a rigid block must lie
# within the range of the stage-3 slip of the deformable wedge along its
# base (measured 0.0395 to 0.0574 m, Newmark 0.0541 m); with FFIELD SXY=0.4
# Newmark (0.017 m) is outside the model's range (0.003 to 0.011 m).
C20, S20, MU = math.cos(math.radians(20.0)), math.sin(math.radians(20.0)), 0.577


def on_segment(p, a, b, tol=1.0):
    ax, ay = b[0] - a[0], b[1] - a[1]
    t = min(1.0, max(0.0, ((p[0] - a[0]) * ax + (p[1] - a[1]) * ay) / (ax * ax + ay * ay)))
    return math.hypot(p[0] - a[0] - t * ax, p[1] - a[1] - t * ay) < tol


P3 = (50.0, 0.0)                                            # daylight of the 20-degree joint
P1 = (-50.99 + 16.45 / math.tan(math.radians(70.0)), 0.0)   # top of the -70-degree joint
tt = ((P3[0] - P1[0]) * S20 - (P3[1] - P1[1]) * C20) / (math.cos(math.radians(70.0)) * S20
                                                         + math.sin(math.radians(70.0)) * C20)
P2 = (P1[0] + tt * math.cos(math.radians(70.0)), P1[1] - tt * math.sin(math.radians(70.0)))


def wedge_base(geo):
    """Contacts of the wedge's base (20-degree joint, P2-P3) and back (-70, P1-P2)."""
    base = [c for c, r in geo.items() if float(r["ANGLE"]) in (110.0, -70.0)
            and float(r["X"]) > P2[0] and on_segment((float(r["X"]), float(r["Y"])), P2, P3)]
    back = [c for c, r in geo.items() if float(r["ANGLE"]) in (20.0, -160.0)
            and on_segment((float(r["X"]), float(r["Y"])), P1, P2)]
    return base, back


def newmark(vx, vy, drive, normal, mass, alpha):
    """Slip along the joint (up-dip, downstream, positive) of the rigid wedge
    on the base whose velocities are vx, vy (rows of time, value)."""
    dv = slip = 0.0
    for (t0, x0), (t1, x1), (_, y0), (_, y1) in zip(vx, vx[1:], vy, vy[1:]):
        dt = t1 - t0
        ax, av, vg = (x1 - x0) / dt, (y1 - y0) / dt, 0.5 * ((x0 + x1) * C20 + (y0 + y1) * S20)
        inertia = -ax * C20 - av * S20 - alpha * (vg + dv)
        normal_t = normal / mass - ax * S20 + av * C20          # normal force per unit mass
        down = drive / mass + inertia - MU * normal_t
        up = drive / mass + inertia + MU * normal_t
        if dv > 0.0 or (dv == 0.0 and down > 0.0):
            dv = max(0.0, dv + down * dt)
        elif dv < 0.0 or up < 0.0:
            dv = min(0.0, dv + up * dt)
        slip += dv * dt
    return slip


t2 = contacts_table(out2, "PRINT -50,55 -35,2 CON FLOW DOM")
pres = {int(f[0]): float(f[1]) for f in header_rows(out2, "  DOMAIN      PRESSURE", 6)}
if len(t2) >= 2 and pres and con in t2[0][1]:
    geo2, dis2 = t2[0][1], t2[1][1]
    base, back = wedge_base(geo2)
    length = [sum(float(geo2[c]["LENGTH"]) for c in cs) for cs in (base, back)]
    check(abs(length[0] - math.dist(P2, P3)) < 0.01 * math.dist(P2, P3)
          and abs(length[1] - math.dist(P1, P2)) < 0.01 * math.dist(P1, P2),
          "the wedge's base and back are covered by the printed contacts (lengths within 1 %)",
          f"{length} vs {math.dist(P2, P3)}, {math.dist(P1, P2)}")
    area = 0.5 * abs((P3[0] - P1[0]) * (P2[1] - P1[1]) - (P2[0] - P1[0]) * (P3[1] - P1[1]))
    mass = 0.00240 * 0.5 * 80.0 * 100.0 + 0.00265 * area       # dam and rock (PROP D, 10^6 kg)
    fx = 0.5 * 0.0098 * 100.0 ** 2                            # reservoir on the dam face
    fy = -9.8 * mass + 0.001 * 9.8 * area - 0.980 * (-40.0 - P1[0])
    for cs, (nx, ny) in ((base, (-S20, C20)), (back, (C20, S20))):
        for c in cs:
            r = geo2[c]
            head = [pres[int(r[k])] if int(r[k]) != 1 else (0.980 if float(r["X"]) < -39.0 else 0.0)
                    for k in ("DOM1", "DOM2")]
            f = 0.5 * sum(head) * float(r["LENGTH"])
            fx, fy = fx + f * nx, fy + f * ny
    drive, normal = fx * C20 + fy * S20, fx * S20 - fy * C20
    print(f"wedge: static safety factor {MU * normal / drive:.3f}, yield acceleration "
          f"{(MU * normal - drive) / (mass * (C20 - MU * S20)):.3f} m/s^2 (horizontal)")
    dn = d3.replace("* SWITCH OFF FLOW", "HIST N=1 XVEL(0.002,-18.2) YVEL(0.002,-18.2)\n"
                    "PRINT -1,1 -19,-17 GRID\n* SWITCH OFF FLOW").replace(
        "\nPRINT HIS 3\n", "\nPRINT HIS 9\nPRINT HIS 10\nPRINT HIS 3\n")
    outn = stage("D3n.dat", dn)
    # the block under the joint: the one of contact 3445's two that is not the wedge's
    # (the wedge's back, the -70-degree joint, is between the wedge and the block upstream)
    lower = ({int(geo2[con][k]) for k in ("BLOCK1", "BLOCK2")}
             - {int(geo2[c][k]) for c in back for k in ("BLOCK1", "BLOCK2")})
    gp = re.findall(r"history 9: XVEL \S+ taken at gridpoint (\d+) \(([^,]+),([^)]+)\)", outn)
    below = [f for f in header_rows(outn, "  GRIDPT   BLOCK             X", 4)
             if gp and f[0] == gp[0][0]]
    check(len(gp) == 1 and math.hypot(float(gp[0][1]) - 0.002, float(gp[0][2]) + 18.2) < 0.05
          and below and {int(below[0][1])} == lower,
          "the base motion is the gridpoint on the joint of the block under it", f"{gp} {below}")
    t3 = contacts_table(out3, "PRINT -50,55 -35,2 CON")
    slips = [abs(float(t3[1][1][c]["SHEAR-DISP"]) - float(dis2[c]["SHEAR-DISP"])) for c in base]
    alpha = 2 * 0.10 * 2 * math.pi * 2                        # DAMP 0.10 2.0 MASS, udec's reading
    nm = newmark(history(outn, 9), history(outn, 10), drive, normal, mass, alpha)
    print(f"Newmark: {nm:.4f} m; the wedge's base slipped {min(slips):.4f} to {max(slips):.4f} m "
          "in stage 3")
    check(min(slips) <= nm <= max(slips),
          "the slip agrees with Newmark's rigid wedge (within the range along the wedge's base)",
          f"{nm} not in [{min(slips)}, {max(slips)}]")
else:
    check(False, "stage 2 prints its contact and domain tables", f"{len(t2)} {len(pres)}")

rows = history(out3, 3)
first = [v for t, v in rows if t <= 0.2]
last = [v for t, v in rows if t > 1.3]
if first and last:
    a, b = sum(first) / len(first), sum(last) / len(last)
    print(f"crest x-displacement: mean {a:.4f} m over the first load cycle, {b:.4f} m over the last")
    check(b > 1.5 * a, "the crest's horizontal displacement accumulates (Fig. D-7)", f"{a} {b}")
else:
    check(False, "crest history printed", str(len(rows)))
finish()
