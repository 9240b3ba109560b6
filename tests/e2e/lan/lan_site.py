"""A small site on one machine for lan_test.py: a Linux bridge in a network namespace of its
own (the switch), and one namespace per host joined to it by a veth pair, as a warehouse's
machines on one subnet would be. Multicast is routed out of each host's `lan0`, the switch
does no IGMP snooping, and everything is named after this process's pid, so parallel runs
never meet. The site is torn down when its `with` block ends, however it ends; namespaces left
by runs that were killed outright are removed by the next run, and the processes started in a
site die with the test (PR_SET_PDEATHSIG).
"""
import ctypes
import os
import re
import shutil
import signal
import subprocess
import time

PREFIX = "edlan"
CLONE_NEWNET = 0x40000000
PR_SET_PDEATHSIG = 1
CAP_NET_ADMIN, CAP_SYS_ADMIN = 12, 21
LIBC = ctypes.CDLL(None, use_errno=True)


class SiteError(Exception):
    """The network could not be set up (a command failed); says which and why."""


def ip(*args):
    done = subprocess.run(["ip", *args], capture_output=True, text=True)
    if done.returncode != 0:
        raise SiteError(f"`ip {' '.join(args)}` failed: {done.stderr.strip()}")
    return done.stdout


def why_not_here():
    """None if namespaces, veth pairs and bridges can be made here; else why not."""
    caps = 0
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("CapEff:"):
                caps = int(line.split()[1], 16)
    for bit, name in ((CAP_NET_ADMIN, "CAP_NET_ADMIN"), (CAP_SYS_ADMIN, "CAP_SYS_ADMIN")):
        if not caps & (1 << bit):
            return f"this process lacks {name} (network namespaces need root or both capabilities)"
    if not shutil.which("ip"):
        return "no `ip` command (iproute2) on PATH"
    probe = f"{PREFIX}{os.getpid()}-probe"
    try:
        ip("netns", "add", probe)
        ip("-n", probe, "link", "add", "probe0", "type", "veth", "peer", "name", "probe1")
        ip("-n", probe, "link", "add", "probebr", "type", "bridge")
    except SiteError as e:
        return f"cannot make a namespace, a veth pair and a bridge: {e}"
    finally:
        subprocess.run(["ip", "netns", "del", probe], capture_output=True)
    return None


def remove_stale_namespaces():
    """Namespaces of earlier runs whose process is gone (a run killed by a timeout)."""
    for line in ip("netns", "list").splitlines():
        match = re.match(rf"({PREFIX}(\d+)-\S+)", line)
        if match and not os.path.exists(f"/proc/{match.group(2)}"):
            subprocess.run(["ip", "netns", "del", match.group(1)], capture_output=True)


def _die_with_parent():
    LIBC.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


class Site:
    def __init__(self, hosts, subnet="10.77.0"):
        self.hosts = list(hosts)
        self.subnet = subnet
        self.prefix = f"{PREFIX}{os.getpid()}"
        self.switch = f"{self.prefix}-switch"
        self.made = []
        self.processes = []

    def namespace(self, host):
        return f"{self.prefix}-{host}"

    def address(self, host):
        return f"{self.subnet}.{10 + self.hosts.index(host)}"

    def port(self, host):
        """The switch's end of the host's cable."""
        return f"port{self.hosts.index(host)}"

    def __enter__(self):
        try:
            self._make()
        except BaseException:
            self.__exit__(None, None, None)
            raise
        return self

    def _make(self):
        ip("netns", "add", self.switch)
        self.made.append(self.switch)
        ip("-n", self.switch, "link", "add", "br0", "type", "bridge", "mcast_snooping", "0")
        ip("-n", self.switch, "link", "set", "br0", "up")
        for host in self.hosts:
            ns = self.namespace(host)
            ip("netns", "add", ns)
            self.made.append(ns)
            ip("-n", ns, "link", "set", "lo", "up")
            ip("-n", self.switch, "link", "add", self.port(host), "type", "veth", "peer", "name",
               "lan0", "netns", ns)
            ip("-n", self.switch, "link", "set", self.port(host), "master", "br0", "up")
            ip("-n", ns, "addr", "add", f"{self.address(host)}/24", "dev", "lan0")
            ip("-n", ns, "link", "set", "lan0", "up")
            ip("-n", ns, "route", "add", "224.0.0.0/4", "dev", "lan0")

    def __exit__(self, *exc):
        for p in self.processes:
            if p.poll() is None:
                p.terminate()
        deadline = time.monotonic() + 5
        for p in self.processes:
            try:
                p.wait(max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        for ns in reversed(self.made):
            subprocess.run(["ip", "netns", "del", ns], capture_output=True)
        self.made.clear()
        return False

    def enter(self, host):
        """Moves the calling thread into `host`'s namespace (its sockets are made there)."""
        fd = os.open(f"/var/run/netns/{self.namespace(host)}", os.O_RDONLY)
        try:
            if LIBC.setns(fd, CLONE_NEWNET) != 0:
                raise SiteError(f"setns into {self.namespace(host)}: "
                                f"{os.strerror(ctypes.get_errno())}")
        finally:
            os.close(fd)

    def start(self, host, argv, log, env=None, stdout=None):
        """Runs `argv` on `host` (`ip netns exec` execs it: the pid is the program's)."""
        with open(log, "w") as err:
            p = subprocess.Popen(["ip", "netns", "exec", self.namespace(host), *argv],
                                 stdout=stdout or err, stderr=err, env=env,
                                 preexec_fn=_die_with_parent)
        self.processes.append(p)
        return p

    def unplug(self, host):
        ip("-n", self.switch, "link", "set", self.port(host), "down")

    def plug(self, host):
        ip("-n", self.switch, "link", "set", self.port(host), "up")
