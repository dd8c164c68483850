"""The user's guide (docs/guide) stays true to the repository:

- every file or folder it names (`examples/...`, `verification/...`,
  `docs/...`, `src/...`, `tools/...`) exists;
- every ctest it names (`verification.X`, `examples.X`, ...) is a test of
  this build;
- every markdown link between its pages resolves;
- the physics pages (deformable blocks, dynamics, flow, heat, structures,
  reinforcement) exist, each naming its deck under examples/ and its ctest;
- no file of the repository holds an absolute path of a build machine
  (/work/, /root/, /home/, /tmp/udec-): the repository must make sense on a
  machine that has only the repository.
usage: guide_current.py ctest build_dir source_dir"""
import os
import re
import subprocess
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish  # noqa: E402

ctest, build, root = sys.argv[1], sys.argv[2], sys.argv[3]
guide = os.path.join(root, "docs", "guide")
pages = sorted(f for f in os.listdir(guide) if f.endswith(".md"))
check(len(pages) >= 6, f"the guide has its pages ({len(pages)})")
listed = subprocess.run([ctest, "-N"], cwd=build, capture_output=True, text=True).stdout
tests = set(re.findall(r"Test\s+#\d+:\s+(\S+)", listed))
for page in pages:
    text = open(os.path.join(guide, page)).read()
    for path in set(re.findall(r"`((?:examples|verification|docs|src|tools)/[A-Za-z0-9_./-]*)`", text)):
        check(os.path.exists(os.path.join(root, path.rstrip("/"))), f"{page}: {path} exists")
    for name in set(re.findall(r"ctests?\s+`([a-z]+\.[A-Za-z0-9_]+)`", text)):
        check(name in tests, f"{page}: ctest {name} exists")
    for link in set(re.findall(r"\]\(([^)#]+\.md)\)", text)):
        check(os.path.exists(os.path.normpath(os.path.join(guide, link))), f"{page}: link {link}")
# the physics pages (issue 24): one page each, each naming a deck under
# examples/ and the ctest that runs it
for page in ("deformable.md", "dynamics.md", "flow.md", "heat.md", "structures.md",
             "reinforcement.md"):
    path = os.path.join(guide, page)
    text = open(path).read() if os.path.exists(path) else ""
    check(bool(text), f"the guide has the page {page}")
    check(re.search(r"`examples/[A-Za-z0-9_/]+\.dat`", text) is not None,
          f"{page} names its deck under examples/")
    check(re.search(r"ctest\s+`(examples|verification)\.[A-Za-z0-9_]+`", text) is not None,
          f"{page} names the ctest that runs its deck")
files = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True).stdout.split()
pattern = re.compile(rb"(/work/|/root/|/home/[a-z]|/tmp/udec-)")
bad = []
for f in files:
    path = os.path.join(root, f)
    if f.endswith((".png", ".h5", ".sav")) or not os.path.isfile(path):
        continue
    if f == "tests/scripts/guide_current.py":
        continue
    with open(path, "rb") as fh:
        if pattern.search(fh.read()):
            bad.append(f)
check(not bad, "no absolute path of a build machine in the repository", " ".join(bad[:20]))
finish()
