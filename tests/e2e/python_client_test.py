#!/usr/bin/env python3
"""python_client_test.py BUILD_DIR: the Python client (clients/python) against a local
cluster (deploy/cluster.sh): the self-contained run's design, a spec far larger than a
datagram (LCM fragments both ways), bad input, and no coordinator; and with bus keys: signed
requests and results with a keyed cluster, an unsigned client unheard, the trailer's checks;
forged fragments against the reassembly's bounds."""
import json
import os
import resource
import shutil
import struct
import subprocess
import sys
import tempfile
import time
import unittest

BUILD = os.path.abspath(sys.argv.pop(1))
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
os.environ["ENVDESIGN_PYTHON_TYPES"] = os.path.join(BUILD, "python")
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
import envdesign_auth  # noqa: E402
import envdesign_client  # noqa: E402

URL = f"udpm://239.255.76.67:{20001 + (os.getpid() % 10000) * 2}?ttl=0"
SAME = ("status", "design", "objective", "terms", "baseline", "tasks",
        "limit_reached")


def installer_python():
    """A Python with setuptools, wheel and venv (Debian's python3-setuptools, python3-wheel,
    python3-venv; deploy/install-deps.sh): what `pip install --no-build-isolation` needs."""
    check = "import setuptools, wheel, venv"
    for python in ("/usr/bin/python3", sys.executable):
        if os.path.exists(python) and subprocess.run([python, "-c", check]).returncode == 0:
            return python
    raise AssertionError("no Python with setuptools and wheel: run deploy/install-deps.sh")


def readme_example():
    """The ```python block of clients/python/README.md, as written."""
    with open(os.path.join(ROOT, "clients", "python", "README.md")) as f:
        text = f.read()
    return text.split("```python\n", 1)[1].split("```", 1)[0]


def self_contained(spec):
    out = subprocess.run([os.path.join(BUILD, "bin", "envdesign"), "design", spec, "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


class PythonClient(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.cluster = ["bash", os.path.join(ROOT, "deploy", "cluster.sh")]
        cls.env = dict(os.environ, ENVDESIGN_BIN=os.path.join(BUILD, "bin"))
        subprocess.run(cls.cluster + ["start", "--planners", "2", "--lcm-url", URL, "--dir",
                                      os.path.join(cls.work, "cluster")], check=True, env=cls.env)

    @classmethod
    def tearDownClass(cls):
        subprocess.run(cls.cluster + ["stop", "--dir", os.path.join(cls.work, "cluster")],
                       env=cls.env)
        shutil.rmtree(cls.work, ignore_errors=True)

    def check(self, spec):
        result, code = envdesign_client.design_result(spec, URL, give_up_after_s=10)
        self.assertEqual(code, 0)
        want = self_contained(spec)
        for key in SAME:
            self.assertEqual(result[key], want[key], key)

    def test_self_contained_result(self):
        self.check(os.path.join(ROOT, "examples", "restaurant", "c-two-tasks-t10.textproto"))
        self.check(os.path.join(ROOT, "tests", "e2e", "data", "warehouse-small", "signs-1.textproto"))

    def test_spec_larger_than_datagrams(self):
        copy = os.path.join(self.work, "big")
        shutil.copytree(os.path.join(ROOT, "examples", "restaurant"), copy)
        with open(os.path.join(copy, "domain.pddl"), "a") as f:  # ~400 KB of comments
            for i in range(5000):
                f.write(f"; padding line {i:05d} " + "x" * 60 + "\n")
        self.check(os.path.join(copy, "c-two-tasks-t10.textproto"))

    def test_bad_input(self):
        with self.assertRaises(envdesign_client.SpecError):
            envdesign_client.design(os.path.join(ROOT, "tests", "data", "design", "bad",
                                                 "missing-file.textproto"), URL)
        with self.assertRaises(envdesign_client.RemoteError) as caught:
            envdesign_client.design(os.path.join(ROOT, "tests", "data", "design", "bad",
                                                 "unknown-action.textproto"), URL,
                                    give_up_after_s=10)
        self.assertEqual(caught.exception.exit_code, 2)
        self.assertIn("unknown-action.textproto:", str(caught.exception))

    def test_no_coordinator(self):
        with self.assertRaises(envdesign_client.RemoteError) as caught:
            envdesign_client.design(os.path.join(ROOT, "examples", "restaurant",
                                                 "a-one-task-t1.textproto"),
                                    URL.replace(URL.split(":")[-1].split("?")[0], "19999"),
                                    give_up_after_s=1, resend_after_s=0.3)
        self.assertEqual(caught.exception.exit_code, 1)


class PythonClientWithKey(unittest.TestCase):
    """A cluster whose services sign and verify with a key (the C++ side of the trailer)."""
    url = URL.replace(URL.split(":")[-1].split("?")[0], str(20002 + (os.getpid() % 10000) * 2))

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.key = os.path.join(cls.work, "bus.key")
        with open(cls.key, "w") as f:
            f.write("# test key\nk1 " + "5a" * 32 + "\n")
        os.chmod(cls.key, 0o600)
        cls.cluster = ["bash", os.path.join(ROOT, "deploy", "cluster.sh")]
        cls.env = dict(os.environ, ENVDESIGN_BIN=os.path.join(BUILD, "bin"))
        subprocess.run(cls.cluster + ["start", "--planners", "1", "--lcm-url", cls.url, "--dir",
                                      os.path.join(cls.work, "cluster"), "--key-file", cls.key],
                       check=True, env=cls.env)

    @classmethod
    def tearDownClass(cls):
        subprocess.run(cls.cluster + ["stop", "--dir", os.path.join(cls.work, "cluster")],
                       env=cls.env)
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_signed_request_gets_the_self_contained_result(self):
        spec = os.path.join(ROOT, "examples", "restaurant", "c-two-tasks-t10.textproto")
        result, code = envdesign_client.design_result(spec, self.url, give_up_after_s=10,
                                               key_file=self.key)
        self.assertEqual(code, 0)
        want = self_contained(spec)
        for key in SAME:
            self.assertEqual(result[key], want[key], key)

    def test_unsigned_request_is_not_heard(self):
        with self.assertRaises(envdesign_client.RemoteError) as caught:
            envdesign_client.design(os.path.join(ROOT, "examples", "restaurant",
                                                 "a-one-task-t1.textproto"), self.url,
                                    give_up_after_s=1.5, resend_after_s=0.3)
        self.assertEqual(caught.exception.exit_code, 1)
        with open(os.path.join(self.work, "cluster", "coordinator.log")) as f:
            log = f.read()
        self.assertIn("dropped a message on ENVDESIGN_REQUEST: unauthenticated", log)

    def test_key_file_others_can_read_is_refused(self):
        loose = os.path.join(self.work, "loose.key")
        shutil.copy(self.key, loose)
        os.chmod(loose, 0o644)
        with self.assertRaises(envdesign_auth.KeyFileError) as caught:
            envdesign_auth.load_key_file(loose)
        self.assertIn("accessible by group or others", str(caught.exception))


class InstalledPackage(unittest.TestCase):
    """The package as a user installs it, against a cluster of its own."""
    url = f"udpm://239.255.76.67:{62000 + os.getpid() % 2000}?ttl=0"  # apart from the others

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.cluster = ["bash", os.path.join(ROOT, "deploy", "cluster.sh")]
        cls.env = dict(os.environ, ENVDESIGN_BIN=os.path.join(BUILD, "bin"))
        subprocess.run(cls.cluster + ["start", "--planners", "1", "--lcm-url", cls.url, "--dir",
                                      os.path.join(cls.work, "cluster")], check=True, env=cls.env)

    @classmethod
    def tearDownClass(cls):
        subprocess.run(cls.cluster + ["stop", "--dir", os.path.join(cls.work, "cluster")],
                       env=cls.env)
        shutil.rmtree(cls.work, ignore_errors=True)

    def test_installed_package_runs_the_readme_example(self):
        """pip installs clients/python offline into a fresh venv (types included); the README's
        example and the envdesign-client command work there, and a bad URL is one line, exit 2."""
        python = installer_python()
        venv = os.path.join(self.work, "venv")
        subprocess.run([python, "-m", "venv", "--system-site-packages", venv], check=True)
        pip = subprocess.run([os.path.join(venv, "bin", "pip"), "install", "--no-build-isolation",
                              "--no-index", os.path.join(ROOT, "clients", "python")],
                             capture_output=True, text=True)
        self.assertEqual(pip.returncode, 0, pip.stdout + pip.stderr)
        clean = dict(os.environ)
        clean.pop("ENVDESIGN_PYTHON_TYPES", None)  # the installed types, not the build's
        spec = os.path.join(ROOT, "examples", "restaurant", "c-two-tasks-t10.textproto")
        want = self_contained(spec)
        example = readme_example().replace("udpm://239.255.76.67:7667?ttl=0", self.url)
        run = subprocess.run([os.path.join(venv, "bin", "python"), "-c", example], cwd=ROOT,
                             env=clean, capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 0, run.stderr)
        # The restaurant (c): the two barriers, 6.513 + 60 + 18.75 (docs/concepts.md).
        self.assertEqual(run.stdout, f"optimal {want['design']} {want['objective']}\n")
        self.assertEqual(want["design"], ["barrier-00-01", "barrier-10-11"])
        self.assertAlmostEqual(want["objective"], 85.263, places=3)
        command = os.path.join(venv, "bin", "envdesign-client")
        run = subprocess.run([command, spec, "--connect", self.url, "--json"], env=clean,
                             capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(json.loads(run.stdout)["objective"], want["objective"])
        run = subprocess.run([command, spec, "--connect", "udpm://10.1.2.3:7667"], env=clean,
                             capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 2)
        self.assertEqual(run.stderr, "envdesign-client: bad LCM URL 'udpm://10.1.2.3:7667': "
                         "10.1.2.3 is not a multicast address (224.0.0.0 to 239.255.255.255)\n")


class Trailer(unittest.TestCase):
    keys = envdesign_auth.parse_keys("new " + "11" * 32 + "\nold " + "22" * 32, "keys")

    def test_round_trip_tamper_replay_and_rotation(self):
        sender, receiver = envdesign_auth.Auth(self.keys), envdesign_auth.Auth(self.keys)
        wire = sender.sign("ENVDESIGN_CANCEL", b"payload")
        self.assertEqual(wire[:7], b"payload")  # what LCM's decoders read
        self.assertEqual(receiver.verify("ENVDESIGN_CANCEL", wire), b"payload")
        self.assertIsNone(receiver.verify("ENVDESIGN_CANCEL", wire))
        self.assertIsNone(receiver.verify("ENVDESIGN_RESULT", sender.sign("ENVDESIGN_CANCEL", b"x")))
        tampered = bytearray(sender.sign("ENVDESIGN_CANCEL", b"payload"))
        tampered[0] ^= 1
        self.assertIsNone(receiver.verify("ENVDESIGN_CANCEL", bytes(tampered)))
        self.assertIsNone(receiver.verify("ENVDESIGN_CANCEL", b"payload"))
        old_signer = envdesign_auth.Auth(self.keys[1:])
        self.assertEqual(receiver.verify("ENVDESIGN_CANCEL", old_signer.sign("ENVDESIGN_CANCEL", b"o")),
                         b"o")
        self.assertEqual(receiver.drops, {("ENVDESIGN_CANCEL", "replayed"): 1,
                                          ("ENVDESIGN_RESULT", "bad-mac"): 1,
                                          ("ENVDESIGN_CANCEL", "bad-mac"): 1,
                                          ("ENVDESIGN_CANCEL", "unauthenticated"): 1})



# Run in another process: forged fragments on the bus, with a genuine fragmented message
# (GENUINE_PAYLOAD on channel GENUINE) published from a real UdpmBus in the middle.
FORGER = r"""
import socket, struct, sys, time
import envdesign_client
group, port, genuine_size = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
MAGIC, PIECE = 0x4C433033, b"f" * 60000
senders = [socket.socket(socket.AF_INET, socket.SOCK_DGRAM) for _ in range(31)]
overrun = senders.pop()
sent = 0
def send(s, sequence, size, offset, number, count, data=PIECE):
    global sent
    s.sendto(struct.pack(">IIIIHH", MAGIC, sequence, size, offset, number, count) + data,
             (group, port))
    sent += 20 + len(data)
    time.sleep(0.0003)  # keep within what the receiver drains: these must arrive
# A message claiming nearly 4 GB, its fragments all at new offsets: the old reassembly kept
# every one (60 MB).
for i in range(1, 1001):
    send(senders[0], 1, 0xFFFFFFF0, i * 60000, i, 65535)
# Six senders, each a message of the largest size taken, every tenth fragment sent twice,
# one that overruns its message each round (old: 36 MB held); then 24 more senders at once.
LARGEST = envdesign_client.UdpmBus.MAX_MESSAGE_BYTES
for r in range(1, 101):
    for k, s in enumerate(senders[:6]):
        for _ in range(1 if r % 10 else 2):
            send(s, 1000 + k, LARGEST, r * 60000, r, 300)
    send(overrun, 5000 + r, 1000, 0, 1, 2)
    if r == 50:
        bus = envdesign_client.UdpmBus(f"udpm://{group}:{port}?ttl=0")
        bus.publish("GENUINE", bytes(i * 7 % 251 for i in range(genuine_size)))
        bus.close()
for r in range(1, 4):
    for k, s in enumerate(senders[6:]):
        send(s, 2000 + k, LARGEST, r * 60000, r, 300)
print(sent)
"""


class ForgedFragments(unittest.TestCase):
    """The client's own fragment reassembly under forged fragments from another process: the
    messages in reassembly and the bytes they hold stay within UdpmBus's bounds while the
    forger sends several times more, the process's peak memory with them, and a genuine
    fragmented message sent in the middle still arrives whole."""
    url = f"udpm://239.255.76.67:{64000 + os.getpid() % 1000}?ttl=0"  # apart from the others

    def test_bounded_and_the_genuine_message_arrives(self):
        Bus = envdesign_client.UdpmBus
        bus = Bus(self.url)
        self.addCleanup(bus.close)
        seen = {"bytes": 0, "partials": 0, "held": 0}
        take = bus._take

        def watched(datagram, sender):  # the bounds after every datagram
            out = take(datagram, sender)
            seen["bytes"] += len(datagram)
            seen["partials"] = max(seen["partials"], len(bus.partial))
            seen["held"] = max(seen["held"], bus.held)
            self.assertEqual(bus.held, sum(p.held() for p in bus.partial.values()))
            return out
        bus._take = watched
        genuine_size = 300000  # 5 fragments
        before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        group, port, _ = envdesign_client.parse_url(self.url)
        forger = subprocess.Popen(
            [sys.executable, "-c", FORGER, group, str(port), str(genuine_size)],
            stdout=subprocess.PIPE, text=True,
            env=dict(os.environ, PYTHONPATH=os.path.join(ROOT, "clients", "python")))
        self.addCleanup(forger.kill)
        genuine = []
        while forger.poll() is None or not genuine:
            message = bus.receive(0.2)
            if message:
                genuine.append(message)
            elif forger.poll() is not None:
                break  # the forger is done and the bus is quiet
        while bus.receive(0.2):  # what is still queued
            pass
        sent = int(forger.communicate(timeout=30)[0])
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
        self.assertEqual(genuine, [("GENUINE", bytes(i * 7 % 251 for i in range(genuine_size)))])
        # Most of the ~100 MB forged arrived, three times the bytes reassembly may hold.
        self.assertGreater(seen["bytes"], 3 * Bus.MAX_BUFFERED_BYTES, f"of {sent} sent")
        self.assertEqual(seen["partials"], Bus.MAX_PARTIALS)
        self.assertLessEqual(seen["held"], Bus.MAX_BUFFERED_BYTES)
        self.assertGreater(seen["held"], Bus.MAX_BUFFERED_BYTES // 2)  # the bound was reached
        self.assertLess(peak - before, Bus.MAX_BUFFERED_BYTES + (16 << 20))
        # Expiry: partial messages untouched for PARTIAL_EXPIRY_S go with the next fragment.
        self.assertGreater(len(bus.partial), 1)
        bus.PARTIAL_EXPIRY_S = 0.3
        time.sleep(0.4)
        bus._take(struct.pack(">IIIIHH", envdesign_client.FRAGMENT_MAGIC, 7, 100, 0, 0, 2) +
                  b"C\0" + b"x" * 50, ("127.0.0.1", 9))
        self.assertEqual(len(bus.partial), 1)
        self.assertEqual(bus.held, 50)


if __name__ == "__main__":
    unittest.main()
