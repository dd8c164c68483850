"""Every deck transcribed from the manual parses with no unknown command or
keyword (udec --check), and the set of decks is complete."""
import glob
import os
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run  # noqa: E402

udec, root = sys.argv[1], sys.argv[2]
decks = sorted(glob.glob(os.path.join(root, "examples", "**", "*.dat"), recursive=True)
               + glob.glob(os.path.join(root, "verification", "**", "*.dat"), recursive=True))
# The manual's decks: Section 2 (tutorial), Section 7.8 cases 1-5, Appendix A
# problems A-F, Appendix B problems A-G.
folders = (["examples/tutorial"] + [f"verification/thermal{i}" for i in range(1, 6)]
           + [f"verification/{c}" for c in "ABCDEF"]
           + [f"examples/application/{c}" for c in "ABCDEFG"])
for folder in folders:
    found = glob.glob(os.path.join(root, folder, "*.dat"))
    check(len(found) > 0, f"decks transcribed in {folder}")
    check(os.path.exists(os.path.join(root, folder, "README.md")), f"README in {folder}")
for deck in decks:
    rc, out = run(udec, ["--check", deck], cwd=os.path.dirname(deck))
    check(rc == 0, f"deck parses: {os.path.relpath(deck, root)}", out)
print(f"{len(decks)} decks checked")
finish()
