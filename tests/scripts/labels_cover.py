"""Every ctest case carries one of the labels unit, e2e, verification, stability,
bench-smoke (tests/CMakeLists.txt), so that `ctest -L` on those five runs everything.

Usage: labels_cover.py CTEST BUILD_DIR
"""
import json
import subprocess
import sys

from udec_test import check, finish

REQUIRED = {"unit", "e2e", "verification", "stability", "bench-smoke"}

ctest, build = sys.argv[1], sys.argv[2]
proc = subprocess.run([ctest, "--test-dir", build, "--show-only=json-v1"],
                      stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
check(proc.returncode == 0, "ctest --show-only=json-v1 runs", proc.stdout[-2000:])
tests = json.loads(proc.stdout).get("tests", []) if proc.returncode == 0 else []
check(len(tests) > 50, f"the test list is read ({len(tests)} tests)")
for test in tests:
    labels = set()
    for prop in test.get("properties", []):
        if prop.get("name") == "LABELS":
            labels.update(prop.get("value", []))
    check(labels & REQUIRED, f"{test['name']} has one of the labels {sorted(REQUIRED)} "
          f"(has {sorted(labels)})")
finish()
