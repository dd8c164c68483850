"""Every command and keyword of UDEC manual (ICG1.5, 1989) Sections 4.5, 4.6
and 7.4 acts: none answers "not yet implemented" / "not yet available"
(issue 22).

The command table comes from the program itself (`udec --commands-md`, made
from the command registry): each command of those sections is run once per
keyword (and per sub-keyword: PRINT BOUNDARY THERMAL, ...) with arguments made
from the keyword's argument letters, on a fresh small model that has zoned
blocks, joints, heat, fluid and a history, in one interactive session (an
input error only ends that line). A line whose output says "not yet" fails
the test, unless it is in NOT_YET_OWNED below.

NOT_YET_OWNED lists what other work in progress still owns (reinforcement,
simply-deformable blocks, the half-plane far field, heat tables). It may only
shrink: an entry that no longer says "not yet" also fails the test, naming the
entry to delete, so that when that work lands, deleting its names here is all
it takes; the list ends empty.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir  # noqa: E402

udec = sys.argv[1]

# "COMMAND" or "COMMAND KEYWORD" or "COMMAND KEYWORD SUBKEYWORD"
NOT_YET_OWNED = set()
# Reinforcement and cables, simply-deformable blocks, the half-plane far field
# and the heat tables landed on 2026-11-26 and left the list.
# Not owned by any work in progress yet (issue 22 debts, named in its note):
# HISTORY SRAT (Application D) left the list on 2026-11-26
# (tests/scripts/history_srat.py). HISTORY FUNCTION (a user-written FPLHIS(n),
# "available to users with source codes only") is refused with a message since
# issue 22 (docs/mechanics.md "Adding a history quantity"): not "not yet".

SECTIONS = {"4.5", "4.6", "7.4"}
# commands that steer the session rather than the model (tested elsewhere)
SKIP = {"STOP", "QUIT", "END", "NEW", "START", "RETURN", "CALL", "HEADING", "HELP"}

SETUP = """NEW
THERMAL
ROUND 0.02
BLOCK 0,0 0,10 10,10 10,0
SPLIT -1,5 11,5
PROP MAT 1 DENS 2000 K 1e9 G 6e8 COND 1 SPEC 1000 THEXP 1e-5
PROP JMAT 1 JKN 2e9 JKS 1e9 JFRIC 0.3 AZERO 1e-4 ARES 5e-5
GEN EDGE 5
FLUID DEN 1000
BOUND -1 11 -0.1 0.1 YVEL 0
THAPP -1 0.1 -1 11 FLUX 1 0
HIST YDIS 5 10
CYC 2
"""

md = run(udec, ["--commands-md"])[1]

# the command index: name -> section
sections = dict(re.findall(r"^\| \[(\S+)\]\(#\S+\) \| \S+ \| (\S+) \|", md, re.M))
check(len(sections) > 50, f"the command table lists the commands ({len(sections)})")


def values(spec, optional=False):
    """Arguments for an argument specification of the table ('r r r r a [p]'):
    without the optional groups, or (`optional`) with them."""
    if optional:
        spec = spec.replace("[", " ").replace("]", " ")
    else:
        while re.search(r"\[[^\[\]]*\]", spec):
            spec = re.sub(r"\[[^\[\]]*\]", " ", spec)   # innermost first
    out, reals = [], iter(["0", "10", "0", "10"])
    for tok in spec.split():
        tok = tok.rstrip("*")
        if tok == "":
            continue
        for letter in tok:
            if letter == "r":
                out.append(next(reals, "1"))
            elif letter in "npicq":
                out.append("1")
            elif letter == "s":
                out.append("walk.tmp")
            elif letter == "a":
                out.append("1")
            elif letter == "R":
                out.append("-1 11 -1 11")
    return " ".join(out)


lines = []          # (label, command line)
for block in re.split(r"^## ", md, flags=re.M)[1:]:
    name = block.split("\n", 1)[0].strip()
    if sections.get(name) not in SECTIONS or name in SKIP:
        continue
    syntax = re.search(r"^    " + re.escape(name) + r"(.*)$", block, re.M)
    positional = syntax.group(1).replace("keyword ..", "") if syntax else ""
    # each line with the optional arguments left out, and once more with them
    # (DAMP fcrit freq INTERNAL: a handler may need them to reach its keyword)
    heads = {(name + " " + values(positional)).strip(),
             (name + " " + values(positional, True)).strip()}
    rows = [r for r in re.findall(r"^\| (\S+) \| \S+ \| ([^|]*) \|[^|]*\|[^|]*\| ([^|]*) \|$",
                                  block, re.M) if r[0] != "keyword"]
    for head in sorted(heads):
        if not rows:
            lines.append((name, head))
        for kw, spec, notes in rows:
            for line in sorted({f"{head} {kw} {values(spec)}".strip(),
                                f"{head} {kw} {values(spec, True)}".strip()}):
                lines.append((f"{name} {kw}", line))
            sub = re.match(r"then (.*)", notes.strip())
            if sub:
                for s in re.findall(r"([A-Z-]+) \(", sub.group(1)):
                    lines.append((f"{name} {kw} {s}", f"{head} {kw} {s}"))

check(len(lines) > 300, f"every keyword of Sections 4.5, 4.6, 7.4 is tried ({len(lines)} lines)")

d = workdir()
setup = SETUP.strip().splitlines()
text = ""
for _, line in lines:
    text += SETUP + line + "\n"
text += "STOP\n"
rc, out = run(udec, [], cwd=d, stdin_text=text, timeout=600)
# interactive: the output of input line k follows the (k+1)-th prompt
segments = out.split("UDEC>")
per = len(setup) + 1
found = set()
for i, (label, line) in enumerate(lines):
    k = i * per + len(setup) + 1
    seg = segments[k] if k < len(segments) else ""
    if re.search(r"not yet (implemented|available)", seg, re.I):
        found.add(label)
        check(label in NOT_YET_OWNED, f"'{line}' answers not yet", seg.strip()[:400])

for label in sorted(NOT_YET_OWNED - found):
    check(False, f"'{label}' no longer answers 'not yet': delete it from NOT_YET_OWNED "
          "in tests/scripts/not_yet_walk.py")
print(f"{len(lines)} lines tried; 'not yet' left, owned elsewhere: {sorted(found)}")
finish()
