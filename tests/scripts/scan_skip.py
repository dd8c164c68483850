"""A CYCLE skips its opening search for new contacts only when nothing can
have come within the contact margin since the last search (label e2e;
issue 23, engine_cycle search_skippable).

The contact update of the manual (UDEC manual (ICG1.5), Section 3.3: new
contacts are searched for as blocks move) searches again once a block has
travelled a quarter of the margin; a CYCLE command searched at its start
in any case. Now it skips that search when no command since the last one
could have changed the contacts and the travel since is under a quarter of
the margin; the travel then carries on into the CYCLE. `SET CSCAN 100`
(stored, no effect, the default value) is a command that is not known to
keep the contacts, so the CYCLE after it searches: the forced search.

Checks:
1. a jointed wall settling under gravity (3 joint sets), CYCLE 300 twice
   after CYCLE 1 and CYCLE 0: PRINT CYCLE says the CYCLEs skipped their
   opening search, and the histories (unbalanced force, two displacements,
   every printed digit) are the same as with the search forced before each
   (the search would have found nothing new: no difference is allowed);
2a. each of CHANGE, DELETE, ROUND, JSET and SET between two CYCLEs makes
   the second one search at its start; after the JSET (a joint through a
   row of blocks, after cycling) the CYCLE has the new joint's contacts;
2b. each of FIX, PROPERTY JKN, BOUNDARY, GRAVITY and LOAD between two
   CYCLEs keeps the last search (they move, cut and round nothing:
   commands_session search_kept), and the histories are, every printed
   digit, those with the search forced after the command;
3. a block sliding down a tilted-gravity plane towards a fixed block 3
   margins away, in 80 CYCLE 5 commands, each travelling less than a
   quarter of the margin: the travel carried across the commands brings the
   search that makes the contact with the fixed block before the two touch,
   so the block is stopped there (its largest x displacement is the 0.03 m
   gap plus at most OVTOL, 0.005 m, of overlap; before a contact exists
   nothing stops it, and a model that never searched again would run on
   into the block: an overlap error or a displacement far past 0.035 m);
   its history matches the run with the search forced before every CYCLE
   to 1e-4 relative (the contact is found at another step, the same bound
   on travel as within one CYCLE).
"""
import re
import sys
from udec_test import check, finish, histories, run_deck, workdir

udec = sys.argv[1]
SKIPPED = "Searches for new contacts: none at the start"
SEARCHED = "Searches for new contacts: at the start"
FORCE = "SET CSCAN 100\n"

WALL = """ROUND 0.01
BLOCK 0,0 0,8 8,8 8,0
JSET 0,0 80,0 0,0 1,0 0,0
JSET 90,0 80,0 0,0 1,0 0,0
JSET 45,0 80,0 0,0 2.3,0 0,0
PROP MAT=1 DENS=2500
PROP JMAT=1 JKN=1E9 JKS=1E9 JFRIC=0.3
FIX -1,9 -1,1
GRAVITY 0 -10
DAMP AUTO
HIST UNBAL
HIST YDIS(4,8)
HIST XDIS(8,4)
CYCLE 1
CYCLE 0
{force}CYCLE 300
PRINT CYCLE
{force}CYCLE 300
PRINT CYCLE
PRINT HIST 1
PRINT HIST 2
PRINT HIST 3
"""


def hist_text(out):
    return out[out.index("PRINT HIST 1"):]


folder = workdir()
_, plain = run_deck(udec, folder, "wall", WALL.format(force=""))
_, forced = run_deck(udec, folder, "wall_forced", WALL.format(force=FORCE))
check(plain.count(SKIPPED) == 2, "1. both CYCLE 300 skip their opening search",
      str(plain.count(SKIPPED)))
check(forced.count(SEARCHED) == 2, "1. SET CSCAN before each CYCLE makes it search",
      str(forced.count(SEARCHED)))
check(len(histories(plain)) == 3 and all(len(t) > 50 for t in histories(plain)),
      "1. three histories printed", str([len(t) for t in histories(plain)]))
check(hist_text(plain) == hist_text(forced),
      "1. histories with the search skipped = with it forced, every printed digit")

# 2a. commands that may change what a search finds (they cut, delete or
# round blocks, or are not shown to be safe): the next CYCLE searches
between = {
    "CHANGE": "CHANGE JMAT=1 JCONS=2\n",
    "DELETE": "DELETE 7,8 7,8\n",
    "ROUND": "ROUND 0.02\n",
    "JSET": "JSET 0,0 80,0 0,0 8,0 0,3.5\n",
    "SET": "SET CSCAN 100\n",
}
for name, line in between.items():
    deck = (WALL.split("{force}")[0] + "CYCLE 50\nPRINT STATUS\n" + line
            + "CYCLE 50\nPRINT CYCLE\nPRINT STATUS\n")
    _, out = run_deck(udec, folder, "between_" + name.lower(), deck,
                      forbidden=("*** Error",))
    check(out.count(SEARCHED) == 1 and SKIPPED not in out,
          f"2a. {name} between two CYCLEs: the second searches at its start",
          out[-1500:])
    if name == "JSET":
        # the joint at y = 3.5 cuts the row of blocks between y = 3 and 4:
        # their halves touch across it, so the contacts grow
        counts = [int(m) for m in re.findall(r"^\s*contacts\s+(\d+)", out, re.M)]
        check(len(counts) == 2 and counts[1] > counts[0] + 8,
              "2a. JSET after cycling: the CYCLE after it has the new joint's contacts",
              str(counts))

# 2b. commands that set loads, fixities, boundary conditions and properties
# (commands_session search_kept, issue 23): the next CYCLE keeps the last
# search, and its histories are, every printed digit, those of the same deck
# with the search forced (SET CSCAN) after the command: the skipped search
# would have found nothing new
kept = {
    "FIX": "FIX 3.2,3.8 7.2,7.8\n",
    "PROPERTY": "PROP JMAT=1 JKN=2E9\n",
    "BOUNDARY": "BOUNDARY -1,9 -1,0.01 XVEL 0\n",
    "GRAVITY": "GRAVITY 0 -9\n",
    "LOAD": "LOAD 3.2,3.8 7.2,7.8 0 -1E3\n",
}
for name, line in kept.items():
    deck = WALL.split("{force}")[0] + "CYCLE 50\n" + line + "{force}CYCLE 50\nPRINT CYCLE\n" \
        + "PRINT HIST 1\nPRINT HIST 2\nPRINT HIST 3\n"
    _, out = run_deck(udec, folder, "kept_" + name.lower(), deck.format(force=""),
                      forbidden=("*** Error",))
    _, outf = run_deck(udec, folder, "kept_" + name.lower() + "_forced",
                       deck.format(force=FORCE), forbidden=("*** Error",))
    check(out.count(SKIPPED) == 1 and SEARCHED not in out,
          f"2b. {name} between two CYCLEs: the second keeps the last search", out[-1500:])
    check(outf.count(SEARCHED) == 1, f"2b. {name}: the forced run searches", outf[-1500:])
    check(len(histories(out)) == 3 and hist_text(out) == hist_text(outf),
          f"2b. {name}: histories with the search kept = with it forced, every printed digit")

SLIDE = """ROUND 0.01
BLOCK 0,0 0,2 4,2 4,0
SPLIT -1,1 5,1
SPLIT 1,1 1,3
SPLIT 1.03,1 1.03,3
DELETE 1.005,1.025 1.1,1.9
PROP MAT=1 DENS=2500
PROP JMAT=1 JKN=1E8 JKS=1E8 JFRIC=0.1
FIX -1,5 -1,0.9
FIX 1.5,5 1.1,3
GRAVITY 3 -10
HIST XDIS(0,2)
"""
_, slide = run_deck(udec, folder, "slide", SLIDE + "CYCLE 5\n" * 80 + "PRINT CYCLE\nPRINT HIST 1\n")
_, slide_f = run_deck(udec, folder, "slide_forced",
                      SLIDE + (FORCE + "CYCLE 5\n") * 80 + "PRINT CYCLE\nPRINT HIST 1\n")
check(SKIPPED in slide and SEARCHED in slide_f, "3. the plain run skips, the forced one searches")
hs, hf = histories(slide), histories(slide_f)
check(len(hs) == 1 and len(hf) == 1 and len(hs[0]) == len(hf[0]) and len(hs[0]) > 30,
      "3. one history each, same rows", str([len(t) for t in hs + hf]))
if hs and hf:
    xs = [v for _, v in hs[0]]
    xf = [v for _, v in hf[0]]
    check(0.0295 < max(xs) < 0.035, "3. the block reaches the fixed one and is stopped there",
          f"max XDIS {max(xs):.6g}")
    worst = max(abs(a - b) for a, b in zip(xs, xf)) / max(abs(v) for v in xf)
    check(worst < 1e-4, "3. same history as with the search forced (1e-4 of the largest)",
          f"{worst:.3g}")
finish()
