"""Issue 24, packaging: `cmake --install <build> --prefix <tmp>` puts udec in
bin/, its manual page in share/man/man1/, the command reference, README and
LICENSE (and docs/guide when the tree has one) in share/doc/udec/; the
installed program runs, names its licence, and prints the manual page that
is installed (docs/udec.1 is current)."""
import os
import shutil
import subprocess
import sys
sys.path.insert(0, os.path.dirname(__file__))
from udec_test import check, finish, run, workdir  # noqa: E402

udec, source, cmake, build = sys.argv[1:5]
prefix = workdir()
p = subprocess.run([cmake, "--install", build, "--prefix", prefix], stdout=subprocess.PIPE,
                   stderr=subprocess.STDOUT, text=True, timeout=120)
check(p.returncode == 0, "cmake --install succeeds (status %d)" % p.returncode, p.stdout[-2000:])

doc = os.path.join(prefix, "share", "doc", "udec")
expected = [os.path.join(prefix, "bin", "udec"),
            os.path.join(prefix, "share", "man", "man1", "udec.1"),
            os.path.join(doc, "commands.md"), os.path.join(doc, "LICENSE"),
            os.path.join(doc, "README.md")]
guide = os.path.join(source, "docs", "guide")
if os.path.isdir(guide):
    for root, _, files in os.walk(guide):
        for f in files:
            rel = os.path.relpath(os.path.join(root, f), os.path.join(source, "docs"))
            expected.append(os.path.join(doc, rel))
for path in expected:
    check(os.path.isfile(path), "installed: " + os.path.relpath(path, prefix))

installed = os.path.join(prefix, "bin", "udec")
check(os.access(installed, os.X_OK), "the installed udec is executable")
rc, out = run(installed, ["--version"])
check(rc == 0 and "BSD-3-Clause" in out, "udec --version names the licence", out)
license_text = open(os.path.join(source, "LICENSE")).read()
check("BSD 3-Clause License" in license_text and "the udec authors" in license_text,
      "LICENSE is BSD-3-Clause, copyright the udec authors")

# the installed manual page is what the program prints (docs/udec.1 current)
rc, man = run(installed, ["--man"])
page = open(os.path.join(prefix, "share", "man", "man1", "udec.1")).read()
check(rc == 0 and man == page, "the installed udec.1 is what udec --man prints")
for name in ("CYCLE", "PROPERTY", "HELP"):
    check("\n.B " + name in man, "the manual page lists " + name)
check(".TH UDEC 1" in man and ".SH LICENSE" in man, "the manual page has its sections")
if shutil.which("man"):
    p = subprocess.run(["man", "-l", "-"], input=man, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True, env=dict(os.environ, MANWIDTH="80"))
    check(p.returncode == 0 and "distinct element" in p.stdout and not p.stderr.strip(),
          "man renders the page without warnings", p.stderr[-1000:])
shutil.rmtree(prefix, ignore_errors=True)
finish()
