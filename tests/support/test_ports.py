"""The one allocator of UDP ports for tests that start an LCM bus: the Python twin of
tests/support/ports.h, over the same claims (read that file for why and how).

    from test_ports import claim_udp_port, udpm_test_url
    url = udpm_test_url(claim_udp_port())
"""

import fcntl
import os
import socket
import sys
import time

FIRST, LAST = 20000, 32767
CLAIMS = "/tmp/envdesign-test-ports"
_held = []  # the claims' open files: a claim lasts as long as the process


def udp_port_is_free(port):
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
        try:
            s.bind(("0.0.0.0", port))
            return True
        except OSError:
            return False


def claim_udp_port():
    os.makedirs(CLAIMS, mode=0o777, exist_ok=True)
    span = LAST - FIRST + 1
    start = (os.getpid() * 7919) % span
    for i in range(span):
        port = FIRST + (start + i) % span
        if (port - 7400) % 250 < 112:  # Cyclone DDS's domain ports
            continue
        try:
            claim = open(os.path.join(CLAIMS, str(port)), "a+")
        except OSError:  # another user's claim file
            continue
        try:
            fcntl.flock(claim, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            claim.close()
            continue
        if udp_port_is_free(port):
            _held.append(claim)
            return port
        claim.close()
    raise RuntimeError(f"no free UDP port for a test in {FIRST}-{LAST}")


def udpm_test_url(port, query="ttl=0"):
    return f"udpm://239.255.76.67:{port}?{query}"


def hold_for(pid):
    """Claims a port, prints it, and keeps the claim in a detached child until process `pid`
    (a shell test: `port=$(python3 tests/support/test_ports.py --held-by $$)`) exits."""
    port = claim_udp_port()
    if os.fork() == 0:  # the child shares the claim's open file, so the lock stays held
        os.setsid()
        devnull = os.open(os.devnull, os.O_RDWR)
        for fd in (0, 1, 2):
            os.dup2(devnull, fd)  # the shell's $(...) waits for stdout to close
        while True:
            try:
                os.kill(pid, 0)
            except ProcessLookupError:
                os._exit(0)
            time.sleep(0.5)
    print(port)


if __name__ == "__main__":
    if len(sys.argv) != 3 or sys.argv[1] != "--held-by":
        sys.exit("usage: test_ports.py --held-by PID")
    hold_for(int(sys.argv[2]))
