#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Runs QEMU for a board with a display and saves its screen.

    qemu_screen.py SCREEN.ppm -- QEMU-COMMAND...

Starts QEMU with its monitor (QMP) on a unix socket, passes QEMU's
stdout (the firmware's image through semihosting) straight on, and copies
its stderr (the firmware's figures) line by line, without QEMU's notes
that say nothing about the run (QEMU_NOISE). When the firmware logs the line
"display_done" (port_display_done() in port/baremetal/board_lm3s6965.c)
the picture is complete: this sends the monitor `screendump`, which writes
SCREEN.ppm (512x256 for the lm3s6965evb OLED), then `quit`. A screendump
first has the display model redraw its memory into the console surface
(hw/display/ssd0323.c draws only then, and only after data changed it);
QEMU 7.2 does that for both monitors. QMP is used for its replies, one
JSON line each. The exit status is QEMU's: 0 after a screendump, or the
firmware's own when it exits without saying it is done (an error or a
fault); SCREEN.ppm is then absent. After a screendump it says "wrote SCREEN.ppm". mk/boards/lm3s6965.mk runs `make qemu` through it.
"""
import json
import os
import signal
import socket
import subprocess
import sys
import tempfile
import time

# QEMU's own notes that say nothing about the run, dropped from the log:
# the lm3s6965evb timer model reports the firmware's unused timers, and
# -icount with sleep=off warns when the firmware, done, waits for nothing.
QEMU_NOISE = (
    b"Timer with period zero, disabling",
    b"qemu-system-arm: warning: icount sleep disabled and no active timers",
)


def copy_line(line):
    """Passes one line of QEMU's stderr on, unless it is QEMU_NOISE."""
    if line.strip() not in QEMU_NOISE:
        sys.stderr.buffer.write(line)
        sys.stderr.flush()


def qmp(path, commands, timeout=30.0):
    """Connects to the QMP monitor at path and runs commands in turn, each
    a (name, arguments) pair; raises OSError on an error reply. The last
    one may end the connection (quit)."""
    deadline = time.monotonic() + timeout
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
        while True:
            try:
                sock.connect(path)
                break
            except (FileNotFoundError, ConnectionRefusedError):
                if time.monotonic() > deadline:
                    raise
                time.sleep(0.05)
        reader = sock.makefile("rb")

        def reply():
            # The next message that is not an asynchronous event.
            while True:
                sock.settimeout(max(0.1, deadline - time.monotonic()))
                line = reader.readline()
                if not line:
                    raise OSError("QMP closed the connection")
                msg = json.loads(line)
                if "event" not in msg:
                    return msg

        reply()  # the greeting
        for i, (name, args) in enumerate(
                [("qmp_capabilities", {})] + commands):
            req = {"execute": name}
            if args:
                req["arguments"] = args
            sock.sendall(json.dumps(req).encode() + b"\n")
            if name == "quit":
                # Closing at once could drop the command unread: wait for
                # QEMU to close the connection as it exits.
                try:
                    while reader.readline():
                        pass
                except OSError:
                    pass
                return
            msg = reply()
            if "error" in msg:
                raise OSError("QMP %s: %s" % (name, msg["error"].get("desc")))


def main(argv):
    if len(argv) < 4 or argv[2] != "--":
        sys.stderr.write(__doc__)
        return 2
    screen, qemu = argv[1], argv[3:]
    if subprocess.run(["sh", "-c", 'command -v "$0"', qemu[0]],
                      stdout=subprocess.DEVNULL).returncode != 0:
        sys.stderr.write("%s not found; install it with: apt-get install "
                         "--no-install-recommends qemu-system-arm\n" % qemu[0])
        return 127
    try:
        os.unlink(screen)
    except FileNotFoundError:
        pass
    tmpdir = tempfile.mkdtemp(prefix="qemu_screen.")
    sock_path = os.path.join(tmpdir, "monitor.sock")
    part = os.path.join(tmpdir, "screen.ppm")
    proc = subprocess.Popen(
        qemu + ["-qmp", "unix:%s,server=on,wait=off" % sock_path],
        stderr=subprocess.PIPE)

    def stop(signum, frame):
        proc.kill()
        sys.exit(128 + signum)
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)

    failed = False
    try:
        for line in proc.stderr:
            copy_line(line)
            if line.strip() == b"display_done":
                try:
                    qmp(sock_path, [("screendump", {"filename": part}),
                                    ("quit", {})])
                except OSError as e:
                    sys.stderr.write("qemu_screen: %s\n" % e)
                    failed = True
                    proc.kill()
                break
        for line in proc.stderr:  # whatever QEMU says on the way out
            copy_line(line)
        rc = proc.wait()
        if not failed and os.path.exists(part):
            os.replace(part, screen)
            sys.stderr.write("wrote %s (the panel, from QEMU's screendump)\n"
                             % screen)
    finally:
        if proc.poll() is None:
            proc.kill()
        for f in (part, sock_path):
            try:
                os.unlink(f)
            except FileNotFoundError:
                pass
        os.rmdir(tmpdir)
    return 1 if failed else rc


if __name__ == "__main__":
    sys.exit(main(sys.argv))
