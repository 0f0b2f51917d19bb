"""Run a planner so that it cannot outlive the tool (run as a script, not imported).

``python guard.py FD COMMAND...``: FD is the read end of a pipe whose only
write end the tool holds.  The guard leads the planner's process group
(``process.run_process_group`` starts it in a new session) and runs COMMAND in that group.
When the tool dies, even by ``kill -9``, the kernel closes the write end;
the guard reads end-of-file and kills the whole group, itself included, at
once, and removes the run's scratch directory (its cwd).  Fast Downward's
driver forks its translator and search, so a parent-death signal on the
driver alone would leave them running.

The guard exits as the planner did (a death by signal N as 256 - N, which
``process`` reads back as -N, as it does for the driver's own codes).
"""

import os
import shutil
import signal
import subprocess
import sys
import threading
import time

# Only a directory an adapter made for this run is removed (tempfile prefix "relevance-plan-").
SCRATCH_PREFIX = "relevance-plan-"


def _watch(fd: int) -> None:
    while True:
        try:
            if not os.read(fd, 1):
                break
        except InterruptedError:
            continue
        except OSError:
            break
    _stop_everything()


def _stop_everything() -> None:
    """Kill the whole group; a detached child then removes the run's scratch
    directory (our cwd), which the dead tool can no longer remove."""
    workdir = os.getcwd()
    if os.path.basename(workdir).startswith(SCRATCH_PREFIX):
        ready_read, ready_write = os.pipe()
        if os.fork() == 0:
            os.setsid()  # leave the group that is about to be killed
            os.close(ready_write)  # tells the guard we are out
            time.sleep(0.5)  # SIGKILL has landed: nobody writes there any more
            shutil.rmtree(workdir, ignore_errors=True)
            os._exit(0)
        os.close(ready_write)
        os.read(ready_read, 1)  # end-of-file once the cleaner has left the group
    os.killpg(0, signal.SIGKILL)


def main() -> None:
    fd = int(sys.argv[1])
    threading.Thread(target=_watch, args=(fd,), daemon=True).start()
    try:
        process = subprocess.Popen(sys.argv[2:], close_fds=True)
    except OSError as error:
        print(f"guard: cannot start {sys.argv[2]}: {error.strerror or error}", file=sys.stderr)
        os._exit(127)
    code = process.wait()
    os._exit(code & 0xFF if code >= 0 else (256 + code) & 0xFF)


if __name__ == "__main__":
    main()
