"""Application A (manual Appendix B, Problem A): first seismic event, the
y-velocity at the top of the model (history 6, YVEL (0,20)), from the deck
as printed (A1_static_seismic_1p25MPa.dat; HIST WRITE lines added).

References and tolerances:
* Manual, Appendix B, Problem A, text to Fig. A-5: the plane-wave estimate
  V = sigma / (2 rho Cp) with the intact rock modulus is "about 0.04 m/sec";
  "Figure A-5 shows a peak velocity of less than 0.06 m/sec", the difference
  being the joints' compliance. Asserted: the wave's own top velocity (the
  deck's history 6 minus the same history of the same deck with the wave's
  amplitude set to 0, which records the residual motion of the excavation
  stage) peaks between 0.04 and 0.06 m/s (measured 0.0594).
* The switch from YVEL 0 to XVISC YVISC keeps the static load (the support's
  reaction becomes the load): without the wave the top moves by less than
  0.025 m/s, the residual motion of the excavation stage (its 2000 cycles
  end with a largest gridpoint velocity of 0.09 m/s); measured 0.020. With
  that stage run to rest (CYCLE 8000 instead of 2000, largest velocity
  7e-5 m/s) the top without the wave stays below 1e-3 m/s (measured
  2.4e-5). Before the fix of the switch under SET FUP (the tractions of
  LSTRESS were counted twice) it moved at 1.1 m/s with no wave.
* The published bound on the deck's own record: with the excavation stage
  run to rest (CYCLE 8000 instead of 2000) the printed deck's history 6
  peaks below 0.06 m/s (manual, Appendix B, Problem A, Fig. A-5: "a peak
  velocity of less than 0.06 m/sec"); measured 0.0594 (2026-11-26). As
  printed (2000 cycles) it peaks at 0.0695: README, "Why the printed deck's
  record exceeds 0.06" (3000 cycles already give 0.0596).
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "..", "verification"))
from common import check, finish, workdir, deck_with, run_deck, read_history  # noqa: E402

udec = sys.argv[1]
deck = os.path.join(os.path.dirname(os.path.abspath(__file__)), "A1_static_seismic_1p25MPa.dat")
folder = workdir()
peaks = {}
series = {}
for label, replace in (("wave", None),
                       ("no wave", [("STRESS 0 0 -1.25", "STRESS 0 0 0.0")])):
    name = "A1.dat" if label == "wave" else "A1_nowave.dat"
    hist = "h6_" + label.replace(" ", "") + ".txt"
    text = deck_with(deck, [f"HIST WRITE 6 {hist}"], replace)
    rc, out, secs = run_deck(udec, folder, name, text)
    check(rc == 0, f"{name} runs", f"rc={rc}, {secs:.1f} s")
    check("history 6: YVEL (0.00000,20.0000) taken at gridpoint" in out,
          f"{label}: history 6 is YVEL at the top (0, 20)")
    t, v = read_history(os.path.join(folder, hist))
    check(len(t) >= 70 and t[-1] > 0.015, f"{label}: history 6 covers the 800 cycles",
          f"{len(t)} samples to t = {t[-1] if t else 0:.4f} s")
    series[label] = v
    peaks[label] = max(abs(x) for x in v)
    print(f"info: {label}: history 6 peak |v| {peaks[label]:.4f} m/s "
          f"(min {min(v):+.4f}, max {max(v):+.4f})")
text = deck_with(deck, ["HIST WRITE 6 h6_rest.txt"], [("STRESS 0 0 -1.25", "STRESS 0 0 0.0"),
                                                       ("CYCLE 2000", "CYCLE 8000")])
rc, out, secs = run_deck(udec, folder, "A1_rest_nowave.dat", text)
check(rc == 0, "A1 with the excavation stage run to rest, no wave, runs", f"rc={rc}, {secs:.1f} s")
t, v = read_history(os.path.join(folder, "h6_rest.txt"))
rest = max(abs(x) for x in v) if v else float("nan")
check(rest < 1e-3, "from rest, the switch to viscous boundaries keeps the top still without "
      "the wave (< 1e-3 m/s)", f"{rest:.2e} m/s")
check(peaks["no wave"] < 0.025, "without the wave the top keeps still within the excavation "
      "stage's residual motion (< 0.025 m/s)", f"{peaks['no wave']:.4f} m/s")
wave = [a - b for a, b in zip(series["wave"], series["no wave"])]
pw = max(abs(x) for x in wave)
check(0.04 < pw < 0.06, "the wave's top velocity peaks between the plane-wave estimate 0.04 and "
      "the manual's 'less than 0.06 m/sec' (Fig. A-5)", f"{pw:.4f} m/s")
# The deck's own record against the published bound, from an excavation stage at rest
text = deck_with(deck, ["HIST WRITE 6 h6_rest_wave.txt"], [("CYCLE 2000", "CYCLE 8000")])
rc, out, secs = run_deck(udec, folder, "A1_rest_wave.dat", text)
check(rc == 0, "A1 with the excavation stage run to rest (CYCLE 8000), with the wave, runs",
      f"rc={rc}, {secs:.1f} s")
t, v = read_history(os.path.join(folder, "h6_rest_wave.txt"))
rest_wave = max(abs(x) for x in v) if v else float("nan")
check(rest_wave < 0.06, "from rest, the deck's history 6 (top y-velocity) peaks below the "
      "manual's 0.06 m/s (Fig. A-5)", f"{rest_wave:.4f} m/s")
finish()
