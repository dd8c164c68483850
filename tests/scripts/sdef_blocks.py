"""Simply-deformable (SDEF) blocks: CHANGE SDEF, CONS 1 and 4 (PROPERTY TF),
DAMP INTERNAL (UDEC manual (ICG1.5, 1989), Section 3.2 p. 3-2, Section 4.5
CHANGE, DAMP and PROPERTY, Section 5.2.4 Fig. 5-2), against closed forms.

Material: rho = 2000, K = 1e9, G = 6e8 Pa, so E = 9KG/(3K+G) = 1.5e9 Pa,
nu = 0.25; plane strain D11 = K + 4G/3 = 1.8e9, D12 = K - 2G/3 = 0.6e9.

1. Uniaxial stress s = -1e6 Pa in x on a free 1 m square SDEF block
   (BOUNDARY STRESS on its two vertical edges, DAMP INTERNAL to rest):
   plane strain exx = s (1 - nu^2) / E = -6.25e-4, eyy = -s nu (1 + nu) / E =
   2.0833e-4; tolerance 1 %. The same through contacts: an SDEF block between
   a fixed rigid base and a zoned (FDEF) platen loaded by syy = -1e6 on its
   top, frictionless joints (JKS 0): eyy = -6.25e-4, exx = 2.0833e-4, within
   1 % (rigid, SDEF and FDEF blocks in one model).
2. Free vibration of a free square SDEF block of side a = 1 m released under
   a suddenly applied stress (undamped): the strain oscillates about its
   static value with the period of the excited mode. Lagrange's equations of
   the uniform-strain field (engine_sdef) give for a square, generalized
   masses rho a^4/12 (exx, eyy) and rho a^4/6 (exy):
     hydrostatic stress: mode exx = eyy, omega^2 = 12 (D11 + D12) / (rho a^2),
                         T = 1.6558e-3 s;
     pure shear stress:  mode exy,      omega^2 = 24 G / (rho a^2),
                         T = 2.3416e-3 s.
   Period from the upward crossings of the mean over ~10 periods, with
   FRACTION fz 0.2 (a step of 0.2 / omega: the central differences' own
   period error 0.17 %); tolerance 2 %.
3. DAMP INTERNAL damps the strain modes only: a free SDEF block falls under
   gravity while a hydrostatic boundary stress rings its strain mode. With
   DAMP 0.2 600 INTERNAL the ringing falls below 1 % of its first amplitude
   while the centroid velocity stays -g t (to 1e-9 relative: nothing damps
   the fall); without damping the ringing keeps > 95 % of its amplitude; with
   the same damping without INTERNAL (whole-block Rayleigh damping) the fall
   is slowed by more than 1 % (so the check can fail).
4. CONS 4 (Griffith, PROPERTY TF): with sp1 >= sp2 (tension positive) a block
   fractures when sp1 >= TF where 3 sp1 + sp2 > 0, and when
   -(sp1 - sp2)^2 / (8 (sp1 + sp2)) >= TF otherwise (Section 4.5 PROPERTY,
   CONS = 4): uniaxial tension fractures at s = TF, uniaxial compression at
   |s| = 8 TF. Loaded (overdamped DAMP INTERNAL, no overshoot) at 0.97 and
   1.03 times each: no fracture below, fracture above; a fractured block
   carries no tension (SIG1 = 0).
5. SAVE / RESTART in mid-vibration continues as the uninterrupted run, to the
   printed digit; the stage list of a rigid model has no SDEF stage.
6. A numerical failure (contact overlap of an SDEF block) ends the CYCLE with
   the model as after the last good step: PRINT SDEF and SAVE still work.
"""
import math
import sys
from udec_test import check, finish, histories, run, tables, workdir, write

udec = sys.argv[1]

RHO, K, G = 2000.0, 1.0e9, 6.0e8
E = 9.0 * K * G / (3.0 * K + G)
NU = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G))
D11, D12 = K + 4.0 * G / 3.0, K - 2.0 * G / 3.0
S = -1.0e6

FREE = """ROUND 0.001
BLOCK 0,0 0,1 1,1 1,0
CHANGE SDEF {cons}
PROP MAT 1 D 2000 K 1E9 G 6E8 {prop}
{gravity}
{bound}
{damp}
HIST NCYC 1 XDIS 1 1
CYCLE {ncyc}
PRINT SDEF
PRINT RIGID
PRINT HIS 1
STOP
"""


def free_block(name, bound, ncyc, damp="", cons="", prop="", gravity="", extra=None):
    d = workdir()
    text = FREE.format(bound=bound, ncyc=ncyc, damp=damp, cons=cons, prop=prop, gravity=gravity)
    write(d, "f.dat", text)
    rc, out = run(udec, ["f.dat"], cwd=d)
    check(rc == 0, f"{name}: deck runs", out[-1500:])
    sd = tables(out, "PRINT SDEF")
    rg = tables(out, "PRINT RIGID")
    h = histories(out)
    check(len(sd) == 1 and len(sd[0]) == 1 and len(rg) == 1 and len(h) == 1,
          f"{name}: PRINT SDEF, RIGID and HIS tables", out[-1500:])
    return sd[0][0], rg[0][0], h[0], out


def period(h):
    """Mean spacing of the upward crossings of the mean (linear interpolation)."""
    mean = sum(v for _, v in h) / len(h)
    ups = []
    for (t0, v0), (t1, v1) in zip(h, h[1:]):
        if v0 < mean <= v1:
            ups.append(t0 + (mean - v0) / (v1 - v0) * (t1 - t0))
    if len(ups) < 3:
        return float("nan"), len(ups)
    return (ups[-1] - ups[0]) / (len(ups) - 1), len(ups)


def amplitude(vals):
    return max(vals) - min(vals)


# 1. uniaxial plane strain, free block and through contacts
exx_ref = S * (1.0 - NU * NU) / E
eyy_ref = -S * NU * (1.0 + NU) / E
sd, _, _, _ = free_block("uniaxial", "BOUND -0.1 0.1 -0.1 1.1 STRESS -1E6 0 0\n"
                         "BOUND 0.9 1.1 -0.1 1.1 STRESS -1E6 0 0", 3000,
                         damp="DAMP 0.5 100 INTERNAL")
print(f"uniaxial: exx {sd['EXX']:.6g} vs {exx_ref:.6g}, eyy {sd['EYY']:.6g} vs {eyy_ref:.6g}")
check(abs(sd["EXX"] / exx_ref - 1.0) < 0.01, "uniaxial sxx: exx = s (1 - nu^2) / E within 1 %",
      f"{sd['EXX']} vs {exx_ref}")
check(abs(sd["EYY"] / eyy_ref - 1.0) < 0.01, "uniaxial sxx: eyy = -s nu (1 + nu) / E within 1 %",
      f"{sd['EYY']} vs {eyy_ref}")
check(abs(sd["SXX"] / S - 1.0) < 0.01 and abs(sd["SYY"]) < 1e-3 * abs(S),
      "uniaxial sxx: block stress sxx = s, syy = 0", str(sd))

PLATEN = """ROUND 0.001
BLOCK 0,-1 0,2 1,2 1,-1
CRACK -1,0 2,0
CRACK -1,1 2,1
CHANGE 0 1 -1 0 MAT 2
CHANGE 0 1 0 1 SDEF
GEN 0 1 1 2 QUAD 0.5
CHANGE 0 1 1 2 CONS 1 MAT 3
FIX 0 1 -1 0
PROP MAT 1 D 2000 K 1E9 G 6E8
PROP MAT 2 D 2000
PROP MAT 3 D 2000 K 1E10 G 6E9
PROP JMAT 1 JKN 1E12 JKS 0 JFRIC 0
BOUND -0.1 1.1 1.9 2.1 STRESS 0 0 -1E6
DAMP AUTO
CYCLE 12000
PRINT SDEF
PRINT CYCLE
STOP
"""
d = workdir()
write(d, "p.dat", PLATEN)
rc, out = run(udec, ["p.dat"], cwd=d)
check(rc == 0, "platen: deck runs", out[-1500:])
sd = tables(out, "PRINT SDEF")
check(len(sd) == 1 and len(sd[0]) == 1, "platen: one SDEF block printed", out[-1500:])
if sd and sd[0]:
    r = sd[0][0]
    print(f"platen: eyy {r['EYY']:.6g} vs {exx_ref:.6g}, exx {r['EXX']:.6g} vs {eyy_ref:.6g}")
    check(abs(r["EYY"] / exx_ref - 1.0) < 0.01,
          "platen (rigid base, SDEF block, zoned platen): eyy = s (1 - nu^2) / E within 1 %",
          f"{r['EYY']} vs {exx_ref}")
    check(abs(r["EXX"] / eyy_ref - 1.0) < 0.01,
          "platen: exx = -s nu (1 + nu) / E within 1 %", f"{r['EXX']} vs {eyy_ref}")
check("block strain" in out and "zone stresses" in out,
      "platen: the SDEF stage runs beside the zone stages", out[-1500:])

# 2. free vibration periods
for name, bound, t_ref in (
        ("hydrostatic", "BOUND -0.1 1.1 -0.1 1.1 STRESS -1E6 0 -1E6",
         2.0 * math.pi / math.sqrt(12.0 * (D11 + D12) / RHO)),
        ("shear", "BOUND -0.1 1.1 -0.1 1.1 STRESS 0 1E6 0",
         2.0 * math.pi / math.sqrt(24.0 * G / RHO))):
    # FRACTION fz 0.2: the strain modes' step 0.2 / omega (2 asin(0.1) / 0.2
    # = 1.0017: the central-difference period within 0.2 % of the closed
    # form, which has no step; at the default fz 1 the step is 1 / omega,
    # and the discrete period 4.5 % short of it)
    sd, _, h, out = free_block(name, bound, 500, damp="FRACTION 0.1 0.2")
    t, n = period(h)
    print(f"{name}: period {t:.6g} s, closed form {t_ref:.6g} s, error {100 * (t / t_ref - 1):.3f} %")
    check(n >= 8 and abs(t / t_ref - 1.0) < 0.02,
          f"free vibration, {name} mode: period {t:.6g} s vs closed form {t_ref:.6g} s within 2 %",
          f"{n} crossings")

# 3. DAMP INTERNAL: ringing damped, the fall not
ring = "BOUND -0.1 1.1 -0.1 1.1 STRESS -1E6 0 -1E6"
runs = {}
for key, damp in (("none", ""), ("internal", "DAMP 0.2 600 INTERNAL"),
                  ("whole", "DAMP 0.2 600")):
    sd, rg, h, out = free_block(f"fall {key}", ring, 1500, damp=damp, gravity="GRAVITY 0 -10")
    tline = [l for l in out.splitlines() if l.startswith("cycle 1500, time")]
    check(len(tline) == 1, f"fall {key}: end-of-cycle line", out[-800:])
    t_end = float(tline[0].split()[3].rstrip(","))
    vals = [v for _, v in h]
    first = amplitude(vals[:60])
    last = amplitude(vals[-60:])
    runs[key] = (rg["Y-VEL"], -10.0 * t_end, first, last)
for key, (vy, vref, first, last) in runs.items():
    print(f"fall {key}: vy {vy:.9g} vs -g t {vref:.9g}; ringing {first:.4g} -> {last:.4g}")
vy, vref, first, last = runs["none"]
check(last > 0.95 * first, "no damping: the strain mode keeps ringing", f"{last} vs {first}")
vy, vref, first, last = runs["internal"]
check(last < 0.01 * first, "DAMP INTERNAL: ringing below 1 % of its first amplitude",
      f"{last} vs {first}")
check(abs(vy / vref - 1.0) < 1e-9, "DAMP INTERNAL: the fall is undamped, vy = -g t",
      f"{vy} vs {vref}")
vy, vref, first, last = runs["whole"]
check(abs(vy / vref - 1.0) > 0.01, "DAMP without INTERNAL damps the fall too (control)",
      f"{vy} vs {vref}")

# 4. Griffith fracture (CONS 4, TF = 1e6)
TF = 1.0e6
over = "DAMP 1.5 604 INTERNAL MASS"
for name, sign, factor in (("tension", 1.0, 1.0), ("compression", -1.0, 8.0)):
    for f, broken in ((0.97, False), (1.03, True)):
        s = sign * factor * TF * f
        bound = (f"BOUND -0.1 0.1 -0.1 1.1 STRESS {s:.6E} 0 0\n"
                 f"BOUND 0.9 1.1 -0.1 1.1 STRESS {s:.6E} 0 0")
        ncyc = 1500 if broken and sign > 0 else 3000
        d = workdir()
        sd, _, _, out = free_block(f"griffith {name} {f}", bound, ncyc, damp=over,
                                   cons="CONS 4", prop="TF 1E6")
        state = out.split("PRINT SDEF")[1].splitlines()[3].split()[-1]
        check(state == ("F" if broken else "E"),
              f"Griffith, uniaxial {name} at {f} x {factor:g} TF: "
              f"{'fractured' if broken else 'intact'}", out.split("PRINT SDEF")[1][:600])
        if broken:
            check(sd["SIG1"] <= 0.0, f"Griffith {name}: a fractured block keeps no tension",
                  str(sd))
        else:
            check(abs(sd["SXX"] / s - 1.0) < 0.01, f"Griffith {name}: intact block at the load",
                  str(sd))

# 5. save / restart in mid-vibration; stage list of a rigid model
d = workdir()
base = """ROUND 0.001
BLOCK 0,0 0,1 1,1 1,0
CHANGE SDEF
PROP MAT 1 D 2000 K 1E9 G 6E8
BOUND -0.1 1.1 -0.1 1.1 STRESS -1E6 3E5 -5E5
DAMP 0.05 600 INTERNAL
CYCLE 37
"""
write(d, "a.dat", base + "SAVE mid.sav\nCYCLE 50\nPRINT SDEF\nSTOP\n")
write(d, "b.dat", "RESTART mid.sav\nCYCLE 50\nPRINT SDEF\nSTOP\n")
rc1, out1 = run(udec, ["a.dat"], cwd=d)
rc2, out2 = run(udec, ["b.dat"], cwd=d)
check(rc1 == 0 and rc2 == 0, "save/restart decks run", out1[-800:] + out2[-800:])
t1 = out1.split("PRINT SDEF")[-1].splitlines()[1:4]
t2 = out2.split("PRINT SDEF")[-1].splitlines()[1:4]
check(t1 == t2 and len(t1) == 3, "SDEF state after RESTART continues as without", f"{t1}\n{t2}")

write(d, "r.dat", "BLOCK 0,0 0,1 1,1 1,0\nPROP MAT 1 D 2000\nGRAV 0 -10\nCYCLE 5\n"
      "PRINT CYCLE\nCHANGE SDEF\nPRINT CYCLE\nSTOP\n")
rc, out = run(udec, ["r.dat"], cwd=d)
parts = out.split("PRINT CYCLE")
check(rc == 0 and len(parts) == 3 and "block strain" not in parts[1] and "block strain" in parts[2],
      "the SDEF stage is in the list only when the model has SDEF blocks", out[-1200:])

# 6. failure: overlap too great, the model stays printable and saveable
OVER = """ROUND 0.01
BLOCK 0,-1 0,2 1,2 1,-1
CRACK -1,0 2,0
CHANGE 0 1 0 2 SDEF
FIX 0 1 -1 0
PROP MAT 1 D 2000 K 1E9 G 6E8
PROP JMAT 1 JKN 1E6 JKS 1E6 JFRIC 0.5
GRAV 0 -1000
CYCLE 3000
PRINT SDEF
SAVE o.sav
STOP
"""
rc, out = run(udec, [], cwd=d, stdin_text=OVER)
check("Contact Overlap Too Great" in out and "model kept as after cycle" in out,
      "overlap of an SDEF block ends the CYCLE with a message", out[-1500:])
after = out.split("Contact Overlap Too Great")[-1]
check("SDEF blocks:" in after and "Model saved" in after and "NaN" not in after,
      "after the failure PRINT SDEF and SAVE work", after[-1500:])

finish()
