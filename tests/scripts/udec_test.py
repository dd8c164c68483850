"""Small helpers shared by the script tests."""
import os
import subprocess
import sys
import tempfile

FAILURES = []


def check(condition, label, detail=""):
    if not condition:
        FAILURES.append(label)
        print("FAIL:", label)
        if detail:
            print("   ", detail.replace("\n", "\n    ")[:3000])


def finish():
    print(f"{len(FAILURES)} failures")
    sys.exit(1 if FAILURES else 0)


def run(udec, args=(), cwd=None, stdin_text=None, timeout=60):
    """Run udec; returns (returncode, stdout+stderr)."""
    proc = subprocess.run([udec, *args], cwd=cwd, input=stdin_text,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                          timeout=timeout, text=True, errors="replace")
    return proc.returncode, proc.stdout


def workdir():
    return tempfile.mkdtemp(prefix="udec-test-")


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path
