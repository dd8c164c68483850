"""Line editing at the UDEC> prompt on a terminal (label e2e; issue 24: line
editing, history and tab completion of commands and keywords, with libedit).

udec runs on a pseudo-terminal. Typed: `hea<TAB> my tunnel` (completes to
`heading`, the title on the same line), `pri<TAB> statu<TAB>` (PRINT STATUS),
then the up arrow and Enter (the history repeats PRINT STATUS), then `stop`.
Expected: no error, the status table printed twice, its heading "my tunnel".
Without libedit the tab stays in the line ("unknown command") and the arrow
is an escape sequence, so each check fails. Skipped (exit 77) when udec was
built without libedit (CMake says so at configure time).
"""
import os
import pty
import select
import subprocess
import sys
import time
from udec_test import check, finish

udec = sys.argv[1]
build = os.path.dirname(os.path.dirname(os.path.abspath(udec)))
cache = os.path.join(build, "CMakeCache.txt")
if os.path.exists(cache) and "LIBEDIT_FOUND:INTERNAL=1" not in open(cache).read():
    print("udec was built without libedit: plain prompt, nothing to test")
    sys.exit(77)

master, slave = pty.openpty()
proc = subprocess.Popen([udec], stdin=slave, stdout=slave, stderr=slave, close_fds=True,
                        cwd=os.environ.get("TMPDIR", "/tmp"))
os.close(slave)
out = b""


def read_for(seconds):
    global out
    end = time.time() + seconds
    while time.time() < end:
        r, _, _ = select.select([master], [], [], 0.1)
        if r:
            try:
                data = os.read(master, 65536)
            except OSError:
                return
            if not data:
                return
            out += data


def send(keys, wait=0.6):
    os.write(master, keys)
    read_for(wait)


read_for(1.5)
send(b"hea\t my tunnel\r")
send(b"pri\t statu\t\r")
send(b"\x1b[A\r")
send(b"stop\r", 1.0)
try:
    proc.wait(timeout=10)
except subprocess.TimeoutExpired:
    proc.kill()
text = out.decode("utf-8", "replace")
check(proc.returncode == 0, "udec ends with status 0 after STOP", f"status {proc.returncode}\n{text[-2000:]}")
check("***" not in text, "no error from the completed and recalled lines", text[-2000:])
check(text.count("boundary stress (SET)") == 2,
      "PRINT STATUS ran twice (tab-completed, then recalled by the up arrow)",
      f"{text.count('boundary stress (SET)')} times\n{text[-2000:]}")
check("my tunnel" in text.split("heading", 2)[-1] if "heading" in text else False,
      "HEADING, completed from 'hea', took the title", text[-2000:])
finish()
