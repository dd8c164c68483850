"""DELETE of a block that spans the model says the rest is cut in two
(label e2e).

UDEC manual (ICG1.5, 1989), Section 4.5, DELETE xl xu yl yu: every block
whose centroid lies in the range goes. A new user excavates a tunnel in
layered rock with a DELETE range around the tunnel; the layers are strips
across the whole model, their centroids at its middle, so the range takes
whole strips: the model falls in two and flies apart under its boundary
stresses (random deck: 190 m of displacement, SOLVE "balanced"). DELETE now
notes the deleted blocks that reach across the whole model.

1. Three strips (CRACK at y = 4 and 6), DELETE 4 6 4 6: the middle strip
   goes, the note names 1 block centred at (5, 5).
2. A TUNNEL in the same strips, DELETE ANN inside it (its three pieces): no note.
3. A pit from the top (a 4 x 2 m block cut at the surface): no note.
4. A tunnel in two crossing joint sets (75 and -15 degrees, spacing 3 and 4 m,
   TUNNEL 0 0 3 16), excavated by the square DELETE -2.9 2.9 -2.9 2.9 a new
   user writes: two rock blocks that wrap around the ring (27 corners each)
   have their centroids in that square but outside the ring, so they go too and
   the roof block above falls into the enlarged opening. DELETE notes them,
   naming the first, whose centroid is outside the ring; DELETE ANN inside the
   ring takes the four core pieces only and says nothing.
5. A crescent of rock under a tunnel (campaign round 5, seed 9): two joint sets
   (9.7 and -73.8 degrees) leave below a TUNNEL of radius 2.415 a block hugging
   its lower arc, concave, whose centroid (9.93, 14.14) lies 2.145 from the
   centre: inside the ring though every other point of the block is outside.
   DELETE ANN xc yc 0 2.405, what a new user writes for the tunnel, takes it
   with the five core pieces; the note names it (before: no note, the test
   looked at the centroid; the opening grew by 1.9 m2 unnoticed).
6. A heading above the springline (campaign round 5, seed 89): TUNNEL, SPLIT at
   the springline, two joint sets; the heading's range (above the springline,
   inside the ring's width) holds no ring centre, yet takes a rock block above
   the ring (centroid (16.89, 16.28)) with the heading: noted (before: the note
   looked only at rings whose centre was in the range). The bench's range
   below then takes the bench alone, no note.
7. A tunnel under a slope (a new user's deck, session 44): two joint sets (35
   and -60 degrees, spacing 3 and 4 m), TUNNEL 30 10 3 16, ROUND 0.05. Near a
   joint the ring's corner moved onto it (0.088 m, the snap reach 0.102) and
   the sliver between the moved side and the joint (0.092 m thick) merged into
   the core piece, whose corner then lies 0.131 m outside the ring polygon:
   DELETE ANN 30 10 0 2.99 takes the four core pieces and no rock, and says
   nothing (before: "2 deleted block(s) lie outside the TUNNEL ring(s)", the
   corner test allowing EDGE or the reach, not both).
"""
import math
import re
import sys
from udec_test import check, finish, run_deck, workdir

udec = sys.argv[1]
folder = workdir()
NOTE = "note: DELETE: 1 deleted block(s) reached across the whole model (the first centred at (5, 5))"


def beyond_note(out):
    """The note on deleted rock outside a TUNNEL ring: (count, x, y) match groups."""
    return re.search(r"note: DELETE: (\d+) deleted block\(s\) lie outside the TUNNEL ring\(s\) "
                     r"that reach into the range \(the first: block \d+, centroid \((\S+), (\S+)\)\)",
                     out)


def deck(name, body):
    return run_deck(udec, folder, name, "round 0.02\nblock 0,0 0,10 10,10 10,0\n" + body + "stop\n")[1]


out = deck("strips", "crack 0,4 10,4\ncrack 0,6 10,6\ndelete 4 6 4 6\n")
check(NOTE in out, "strips: the note", out[-1500:])
out = deck("tunnel", "crack 0,4 10,4\ncrack 0,6 10,6\ntunnel 5 5 1.5 16\ndelete ann 5 5 0 1.4\n")
check("DELETE: 3 block(s) deleted" in out and "reached across" not in out, "tunnel: no note",
      out[-1500:])
out = deck("pit", "crack 3,10 3,8\ncrack 3,8 7,8\ncrack 7,8 7,10\ndelete 3 7 8 10\n")
check("DELETE: 1 block(s) deleted" in out and "reached across" not in out, "pit: no note",
      out[-1500:])

JOINTED = ("round 0.05\nblock -20,-20 -20,20 20,20 20,-20\n"
           "jset 75,0 100,0 0,0 3,0 (0,0)\njset -15,0 100,0 0,0 4,0 (0,0)\ntunnel 0,0 3 16\n")
out = run_deck(udec, folder, "square", JOINTED + "delete -2.9 2.9 -2.9 2.9\nstop\n")[1]
m = beyond_note(out)
check(m is not None and int(m.group(1)) == 2
      and math.hypot(float(m.group(2)), float(m.group(3))) > 3.0,
      "square range around a tunnel: notes the 2 rock blocks beyond the ring", out[-1500:])
out = run_deck(udec, folder, "annulus", JOINTED + "delete ann 0 0 0 2.9\nstop\n")[1]
check("DELETE: 4 block(s) deleted" in out and "outside the TUNNEL" not in out,
      "annulus inside the ring: the core only, no note", out[-1500:])


def one_noted(name, geometry, deletes, ndel, xc, yc, r, centroid_inside):
    """Run geometry + deletes; True when the first DELETE took ndel blocks and
    noted one block outside the ring (xc, yc, r), its centroid inside the
    circle or not as given."""
    out = run_deck(udec, folder, name, geometry + deletes + "stop\n")[1]
    m = beyond_note(out)
    return out, (f"DELETE: {ndel} block(s) deleted" in out and m is not None and int(m.group(1)) == 1
                 and (math.hypot(float(m.group(2)) - xc, float(m.group(3)) - yc) < r) == centroid_inside)


CRESCENT = ("round 0.02\nblock 0,0 0,30 30,30 30,0\ntunnel 9.688,16.267 2.415 20\n"
            "tunnel 20.312,16.267 2.415 16\njset 9.7,0 60,0 0,0 2.87,0 (1.36,0.66)\n"
            "jset -73.8,0 60,0 0,0 4.10,0 (3.24,0.82)\n")
out, ok = one_noted("crescent", CRESCENT, "delete ann 9.688 16.267 0 2.405\n", 6, 9.688, 16.267, 2.415, True)
check(ok, "crescent under the tunnel, centroid inside the ring: noted", out[-1500:])

HEADING = ("round 0.02\nblock 0,0 0,30 30,30 30,0\ntunnel 15,14.63 2.385 20\n"
           "split 12.115,14.63 17.885,14.63\njset -67.9,0 60,0 0,0 4.73,0 (3.30,2.41)\n"
           "jset 11.2,0 60,0 0,0 2.91,0 (2.71,2.79)\n")
out, ok = one_noted("heading", HEADING, "delete 12.625,17.375 14.64,17.005\n"
                    "delete 12.625,17.375 12.255,14.62\n", 2, 15, 14.63, 2.385, False)
check(ok and out.count("outside the TUNNEL") == 1 and "DELETE: 1 block(s) deleted, 92 remain" in out,
      "heading range holding no ring centre: the rock block above noted, the bench not", out[-1500:])

SLOPE = ("round 0.05\nblock 0,0 0,35 15,35 30,20 60,20 60,0\njset 35,0 100,0 0,0 3,0\n"
         "jset -60,0 100,0 0,0 4,0\ntunnel 30,10 3 16\n")
out = run_deck(udec, folder, "slope", SLOPE + "delete ann 30 10 0 2.99\nstop\n")[1]
check("DELETE: 4 block(s) deleted" in out and "outside the TUNNEL" not in out,
      "slope tunnel: the core pieces with a merged sliver at a snapped corner, no note", out[-1500:])

finish()
