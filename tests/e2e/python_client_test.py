#!/usr/bin/env python3
"""python_client_test.py BUILD_DIR: the Python client (clients/python) against a local
cluster (deploy/cluster.sh): the self-contained run's design, a spec far larger than a
datagram (LCM fragments both ways), bad input, and no coordinator."""
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
import envdesign_client  # noqa: E402

URL = f"udpm://239.255.76.67:{20001 + (os.getpid() % 10000) * 2}?ttl=0"
SAME = ("status", "design", "objective", "terms", "baseline", "tasks",
        "limit_reached")


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
        result, code = envdesign_client.design(spec, URL, give_up_after_s=10)
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


if __name__ == "__main__":
    unittest.main()
