#!/usr/bin/env python3
"""python_client_test.py BUILD_DIR: the Python client (clients/python) against a local
cluster (deploy/cluster.sh): the self-contained run's design, a spec far larger than a
datagram (LCM fragments both ways), bad input, and no coordinator; and with bus keys: signed
requests and results with a keyed cluster, an unsigned client unheard, the trailer's checks;
forged fragments against the reassembly's bounds."""
import json
import os
import re
import resource
import shutil
import socket
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

sys.path.insert(0, os.path.join(ROOT, "tests", "support"))
from test_ports import claim_udp_port, udpm_test_url  # noqa: E402

URL = udpm_test_url(claim_udp_port())
SAME = ("status", "design", "objective", "terms", "baseline", "tasks",
        "limit_reached")


def install_line():
    """The install command of clients/python/README.md (its one indented line naming
    install.sh); README.md and docs/ may name only this line."""
    def lines(path):
        with open(path) as f:
            return [line.strip() for line in f if line.startswith("    ") and
                    "clients/python/install.sh" in line and not line.strip().startswith("#")]
    found = lines(os.path.join(ROOT, "clients", "python", "README.md"))
    assert len(found) == 1, f"clients/python/README.md: {found}"
    for doc in [os.path.join(ROOT, "README.md")] + [
            os.path.join(d, f) for d, _, files in os.walk(os.path.join(ROOT, "docs"))
            for f in files if f.endswith(".md")]:
        for other in lines(doc):
            assert other == found[0], f"{doc} installs with '{other}', not '{found[0]}'"
    return found[0]


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

    def test_warnings_reach_the_python_client(self):
        # They travel in design_result_t: the same lines as `envdesign design --json` prints.
        spec = os.path.join(ROOT, "tests", "data", "usability", "unsolvable-tasks.textproto")
        result, _ = envdesign_client.design_result(spec, URL, give_up_after_s=10)
        cli = subprocess.run([os.path.join(BUILD, "bin", "envdesign"), "design", spec, "--json"],
                             capture_output=True, text=True)
        self.assertEqual(cli.returncode, 3, cli.stderr)  # proven: no design has a finite objective
        want = json.loads(cli.stdout)
        self.assertEqual(len(result["warnings"]), 3, result)
        self.assertEqual(result["warnings"], want["warnings"])

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
                                    udpm_test_url(claim_udp_port()),
                                    give_up_after_s=1, resend_after_s=0.3)
        self.assertEqual(caught.exception.exit_code, 1)


class SameTextAsTheCli(unittest.TestCase):
    """envdesign-client prints what the C++ CLI prints, byte for byte, on every example: its
    output against `envdesign watch` on the same bus, which prints each result it hears with
    the CLI's own formatter (result_text), so both format the very message the coordinator
    sent (a second run's counts, e.g. break-even's designs evaluated in full, may differ)."""
    url = udpm_test_url(claim_udp_port())
    CASES = [["examples/restaurant/a-one-task-t1.textproto"],
             ["examples/restaurant/b-two-tasks-t1.textproto"],
             ["examples/restaurant/c-two-tasks-t10.textproto"],
             ["examples/restaurant/c-two-tasks-t10.textproto", "--ranking", "3"],
             ["examples/restaurant/c-two-tasks-t10-explaining.textproto"],
             ["examples/restaurant/d-cost-optimal-t10.textproto"],
             ["examples/blocksworld/design.textproto"],
             ["examples/blocksworld/design.textproto", "--max-design-size", "1",
              "--search", "exhaustive"],
             ["tests/data/usability/unsolvable-tasks.textproto"]]  # exit 3, with the reason

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.cluster = ["bash", os.path.join(ROOT, "deploy", "cluster.sh")]
        cls.env = dict(os.environ, ENVDESIGN_BIN=os.path.join(BUILD, "bin"))
        subprocess.run(cls.cluster + ["start", "--planners", "2", "--lcm-url", cls.url, "--dir",
                                      os.path.join(cls.work, "cluster")], check=True, env=cls.env)
        cls.watch_out = open(os.path.join(cls.work, "watch.txt"), "w+")
        cls.watch = subprocess.Popen([os.path.join(BUILD, "bin", "envdesign"), "watch",
                                      "--connect", cls.url, "--status"], stdout=cls.watch_out)
        while "status coordinator" not in cls.watched():  # it hears the bus
            time.sleep(0.1)

    @classmethod
    def tearDownClass(cls):
        cls.watch.terminate()
        cls.watch.wait()
        cls.watch_out.close()
        subprocess.run(cls.cluster + ["stop", "--dir", os.path.join(cls.work, "cluster")],
                       env=cls.env)
        shutil.rmtree(cls.work, ignore_errors=True)

    @classmethod
    def watched(cls):
        with open(cls.watch_out.name) as f:
            return f.read()

    def watched_result(self, client):
        """The text `envdesign watch` printed for the result to `client`."""
        for _ in range(50):
            lines = self.watched().splitlines(keepends=True)
            header = [i for i, line in enumerate(lines) if line.startswith(f"result {client}#")]
            if header:
                block = []
                for line in lines[header[0] + 1:]:
                    if line.startswith(("result ", "progress ", "status ", "distribution ")):
                        break
                    block.append(line)
                return "".join(block)
            time.sleep(0.1)
        self.fail(f"envdesign watch printed no result for {client}")

    def run_python(self, args, code=0):
        """(output, envdesign watch's text of the same result) of envdesign-client `args`,
        which exits with `code`."""
        client = subprocess.Popen([sys.executable,
                                   os.path.join(ROOT, "clients", "python", "envdesign_client.py"),
                                   *args, "--connect", self.url], cwd=ROOT,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        out, err = client.communicate(timeout=120)
        self.assertEqual(client.returncode, code, err)
        return out, self.watched_result(f"python-client/{socket.gethostname()}/{client.pid}")

    def test_every_example_prints_what_the_cli_prints(self):
        for args in self.CASES:
            with self.subTest(args=" ".join(args)):
                code = 3 if "unsolvable" in args[0] else 0
                out, cli_text = self.run_python(args, code)
                self.assertEqual(out, cli_text)

    def test_the_text_carries_the_answer(self):
        """The restaurant (c): the numbers a reader takes from it (docs/concepts.md), rounded
        as the CLI rounds them, not the JSON's float noise; the C++ CLI's own run opens with
        the same three lines."""
        out, _ = self.run_python(["examples/restaurant/c-two-tasks-t10.textproto",
                                  "--ranking", "3"])
        lines = out.splitlines()
        self.assertEqual(lines[:3], [
            "status: optimal", "design: {barrier-00-01, barrier-10-11}",
            "objective: 85.26 = 6.513 inexplicability (1 x 6.513) + 60 design cost (30 x 2) + "
            "18.75 robot cost (0.25 x 75)"])
        for expected in ("value of each chosen modification (the objective without it):",
                         "break-even (among the ", "ranking:",
                         "  1. 85.26  {barrier-00-01, barrier-10-11}"):
            self.assertTrue(any(line.startswith(expected) for line in lines), expected)
        self.assertIsNone(re.search(r"[0-9]\.[0-9]{5}", out))  # no float noise
        cli = subprocess.run([os.path.join(BUILD, "bin", "envdesign"), "design",
                              "examples/restaurant/c-two-tasks-t10.textproto", "--ranking", "3",
                              "--connect", self.url], cwd=ROOT, capture_output=True, text=True,
                             timeout=120)
        self.assertEqual(cli.returncode, 0, cli.stderr)
        self.assertEqual(cli.stdout.splitlines()[:3], lines[:3])


SWITCHES_DOMAIN = """(define (domain switches) (:requirements :strips)
  (:predicates (off ?s) (on ?s))
  (:action flip :parameters (?s) :precondition (off ?s) :effect (and (on ?s) (not (off ?s)))))
"""


def write_switches_spec(folder):
    """A spec whose blind search never ends (30 switches: tests/e2e/never_ending_spec.h)."""
    os.makedirs(folder, exist_ok=True)
    names = [f"s{i}" for i in range(30)]
    with open(os.path.join(folder, "domain.pddl"), "w") as f:
        f.write(SWITCHES_DOMAIN)
    with open(os.path.join(folder, "all-on.pddl"), "w") as f:
        f.write(f"(define (problem all-on) (:domain switches) (:objects {' '.join(names)}) "
                f"(:init {' '.join(f'(off {n})' for n in names)}) "
                f"(:goal (and {' '.join(f'(on {n})' for n in names)})))\n")
    with open(os.path.join(folder, "design.textproto"), "w") as f:
        f.write('robot_domain: "domain.pddl"\ntask { name: "all-on" problem: "all-on.pddl" }\n'
                'modification { name: "first-on" cost: 1 edit { model: HUMAN add_init: '
                '"(on s0)" } }\n')
    return os.path.join(folder, "design.textproto")


class PythonClientKeepsItsRequest(unittest.TestCase):
    """The Python client says every 2 s that it still waits: a coordinator with
    --client-timeout 3 keeps its 6 s search, and drops it once the client is killed."""
    url = udpm_test_url(claim_udp_port())

    def setUp(self):
        self.work = tempfile.mkdtemp()
        self.spec = write_switches_spec(os.path.join(self.work, "switches"))
        self.log = os.path.join(self.work, "coordinator.log")
        bin_dir = os.path.join(BUILD, "bin")
        with open(self.log, "w") as log, open(os.devnull, "w") as quiet:
            self.services = [
                subprocess.Popen([os.path.join(bin_dir, "envdesign-coordinator"), "--lcm-url",
                                  self.url, "--name", "coordinator", "--client-timeout", "3"],
                                 stdout=log, stderr=log),
                subprocess.Popen([os.path.join(bin_dir, "envdesign-planner"), "--lcm-url",
                                  self.url, "--name", "planner-0"], stdout=quiet, stderr=quiet)]
        time.sleep(2)  # the coordinator is past its discovery and knows the planner

    def tearDown(self):
        for service in self.services:
            service.terminate()
            service.wait()
        shutil.rmtree(self.work, ignore_errors=True)

    def coordinator_log(self):
        with open(self.log) as f:
            return f.read()

    def test_a_live_client_is_kept_past_the_timeout(self):
        start = time.monotonic()
        _, code = envdesign_client.design_message(self.spec, self.url, time_limit_s=6,
                                                  heuristic="blind", give_up_after_s=30)
        self.assertEqual(code, 4)
        self.assertGreater(time.monotonic() - start, 5.5)
        self.assertNotIn("dropped", self.coordinator_log())

    def test_a_killed_client_is_dropped(self):
        client = subprocess.Popen([sys.executable,
                                   os.path.join(ROOT, "clients", "python", "envdesign_client.py"),
                                   self.spec, "--connect", self.url, "--heuristic", "blind",
                                   "--time-limit", "0"], stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL)
        time.sleep(5)
        self.assertNotIn("dropped", self.coordinator_log())
        client.kill()
        client.wait()
        end = time.monotonic() + 6
        while "dropped: nothing heard" not in self.coordinator_log() and time.monotonic() < end:
            time.sleep(0.1)
        self.assertIn("dropped: nothing heard from its client", self.coordinator_log())


class PythonClientWithKey(unittest.TestCase):
    """A cluster whose services sign and verify with a key (the C++ side of the trailer)."""
    url = udpm_test_url(claim_udp_port())

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
    url = udpm_test_url(claim_udp_port())

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

    def test_install_line_as_written_then_the_readme_example(self):
        """The README's install line, run as written from the repository (HOME a scratch
        folder: the venv goes to its ~/.local/share/envdesign/venv), offline; there the
        README's example and the envdesign-client command work, without the build's types,
        and a bad URL is one line, exit 2."""
        line = install_line()
        self.assertEqual(line, "bash clients/python/install.sh")
        home = os.path.join(self.work, "home")
        os.makedirs(home)
        clean = dict(os.environ, HOME=home)
        clean.pop("ENVDESIGN_PYTHON_TYPES", None)  # the installed types, not the build's
        install = subprocess.run(line, shell=True, cwd=ROOT, env=clean, capture_output=True,
                                 text=True, timeout=300)
        self.assertEqual(install.returncode, 0, install.stdout + install.stderr)
        venv = os.path.join(home, ".local", "share", "envdesign", "venv")
        self.assertIn(f"envdesign-client installed in {venv}", install.stdout)
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
        run = subprocess.run([command, spec, "--connect", self.url], env=clean,
                             capture_output=True, text=True, timeout=60)
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertTrue(run.stdout.startswith(
            "status: optimal\ndesign: {barrier-00-01, barrier-10-11}\nobjective: 85.26 = "),
            run.stdout)
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
    url = udpm_test_url(claim_udp_port())

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
