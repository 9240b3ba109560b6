#!/usr/bin/env python3
"""python_client_test.py BUILD_DIR: the Python client (clients/python) against a local
cluster (deploy/cluster.sh): the self-contained run's design, a spec far larger than a
datagram (LCM fragments both ways), bad input, and no coordinator; and with bus keys: signed
requests and results with a keyed cluster, an unsigned client unheard, the trailer's checks."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
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


if __name__ == "__main__":
    unittest.main()
