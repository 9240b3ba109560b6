#!/usr/bin/env python3
"""two_clusters_test.py BUILD_DIR: two clusters on one bus (issue 25, item 6), real processes
over LCM udpm on loopback.

deploy/cluster.sh started twice on one URL with other --dir: every process keeps its default
name ROLE/HOST/PID, so `envdesign status` shows the four as four names and no shared one, the
later coordinator stands by, every request (the C++ CLI's, the Python client's, a bad one) is
answered exactly once and only by the earlier coordinator, and a job is done only by the
planner it is addressed to (never by a namesake in the other cluster). Services given one
--name on purpose still answer once, and status says which names are shared."""
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
import unittest

BUILD = os.path.abspath(sys.argv.pop(1))
ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
os.environ["ENVDESIGN_PYTHON_TYPES"] = os.path.join(BUILD, "python")
sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
import envdesign_client  # noqa: E402
from envdesign import design_progress_t, design_result_t, evaluation_t, job_t  # noqa: E402
sys.path.insert(0, os.path.join(ROOT, "tests", "support"))
from test_ports import claim_udp_port, udpm_test_url  # noqa: E402

ENVDESIGN = os.path.join(BUILD, "bin", "envdesign")
RESTAURANT = os.path.join(ROOT, "examples", "restaurant")


def port_url(_name):
    """A port of this test's own (tests/support/test_ports.py)."""
    return udpm_test_url(claim_udp_port())


def wait_for(path, text, timeout_s=15):
    end = time.monotonic() + timeout_s
    while time.monotonic() < end:
        if os.path.exists(path):
            with open(path) as f:
                if text in f.read():
                    return True
        time.sleep(0.1)
    return False


class Answers:
    """Every result, progress, job and evaluation on the bus, with the UDP source address of
    the process that sent it (two processes with one name never share a socket)."""

    def __init__(self, url):
        self.bus = envdesign_client.UdpmBus(url)
        take = self.bus._take

        def with_source(datagram, sender):  # receive() then gives (channel, payload, source)
            message = take(datagram, sender)
            return (*message, sender) if message else None
        self.bus._take = with_source
        self.results, self.progress = {}, {}  # (client, request_id) -> [source]
        self.jobs = {}  # (coordinator, job_id) -> {planner addressed}
        self.job_senders = set()  # (coordinator name, source)
        self.evaluations = []  # (coordinator, job_id, planner name, source)
        self.stop = False
        self.thread = threading.Thread(target=self.listen)
        self.thread.start()

    def listen(self):
        while not self.stop:
            message = self.bus.receive(0.1)
            if message:
                self.keep(*message)

    def keep(self, channel, payload, source):
        if channel == "ENVDESIGN_RESULT":
            r = design_result_t.decode(payload)
            self.results.setdefault((r.client, r.request_id), []).append(source)
        elif channel == "ENVDESIGN_PROGRESS":
            p = design_progress_t.decode(payload)
            self.progress.setdefault((p.client, p.request_id), []).append(source)
        elif channel == "ENVDESIGN_JOB":
            j = job_t.decode(payload)
            self.jobs.setdefault((j.sender, j.job_id), set()).add(j.planner)
            self.job_senders.add((j.sender, source))
        elif channel == "ENVDESIGN_EVALUATION":
            e = evaluation_t.decode(payload)
            self.evaluations.append((e.coordinator, e.job_id, e.sender, source))

    def close(self):
        self.stop = True
        self.thread.join()
        self.bus.close()

    def of(self, client):
        """{request: (results, sources of its results and progress)} of `client`."""
        out = {}
        for key, sources in self.results.items():
            if key[0] == client:
                out[key] = (len(sources), set(sources) | set(self.progress.get(key, [])))
        return out

    def processes_by_planner(self):
        """{planner name: UDP sources of the evaluations sent under it}."""
        out = {}
        for _, _, planner, source in self.evaluations:
            out.setdefault(planner, set()).add(source)
        return out


def status_rows(url):
    """(JSON rows, table) of `envdesign status` on `url`: both listen at once (2.5 s)."""
    runs = [subprocess.Popen([ENVDESIGN, "status", *flags, "--connect", url, "--seconds", "2.5"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
            for flags in (["--json"], [])]
    (lines, lines_err), (table, table_err) = (run.communicate(timeout=30) for run in runs)
    assert runs[0].returncode == 0 and runs[1].returncode == 0, lines_err + table_err
    return [json.loads(line) for line in lines.splitlines()], table


def design_cli(url, spec):
    return subprocess.run([ENVDESIGN, "design", os.path.join(RESTAURANT, spec), "--json",
                           "--connect", url], capture_output=True, text=True, timeout=120)


def bad_request(test, url):
    """A request every coordinator refuses (exit code 2): a refusal is an answer too."""
    with test.assertRaises(envdesign_client.RemoteError) as bad:
        envdesign_client.design(os.path.join(RESTAURANT, "a-one-task-t1.textproto"), url,
                                ranking=-1, give_up_after_s=10)
    test.assertEqual(bad.exception.exit_code, 2)


def python_client():
    return f"python-client/{socket.gethostname()}/{os.getpid()}"


class TwoClustersStartedAlike(unittest.TestCase):
    """Two deploy/cluster.sh clusters with their defaults (one planner each), other --dir."""
    url = port_url(0)

    @classmethod
    def setUpClass(cls):
        cls.work = tempfile.mkdtemp()
        cls.env = dict(os.environ, ENVDESIGN_BIN=os.path.join(BUILD, "bin"))
        cls.dirs = [os.path.join(cls.work, name) for name in ("a", "b")]
        for folder in cls.dirs:
            subprocess.run(["bash", os.path.join(ROOT, "deploy", "cluster.sh"), "start",
                            "--planners", "1", "--lcm-url", cls.url, "--dir", folder],
                           check=True, env=cls.env, capture_output=True)
        cls.coordinators = [cls.bus_name(folder, "coordinator") for folder in cls.dirs]
        cls.planners = [cls.bus_name(folder, "planner-1") for folder in cls.dirs]
        cls.logs = [os.path.join(folder, "coordinator.log") for folder in cls.dirs]
        assert wait_for(cls.logs[0], "active: no coordinator that started earlier"), cls.logs[0]
        assert wait_for(cls.logs[1], f"standing by: coordinator {cls.coordinators[0]} started "
                                     "earlier"), cls.logs[1]

    @classmethod
    def tearDownClass(cls):
        for folder in cls.dirs:
            subprocess.run(["bash", os.path.join(ROOT, "deploy", "cluster.sh"), "stop", "--dir",
                            folder], env=cls.env, capture_output=True)
        shutil.rmtree(cls.work, ignore_errors=True)

    @staticmethod
    def bus_name(folder, file):
        """The services' default name, ROLE/HOST/PID, of the process cluster.sh started."""
        with open(os.path.join(folder, file + ".pid")) as f:
            return f"{file.split('-')[0]}/{socket.gethostname()}/{f.read().strip()}"

    def log(self, i):
        with open(self.logs[i]) as f:
            return f.read()

    def test_every_request_is_answered_once_by_the_active_coordinator(self):
        answers = Answers(self.url)
        self.addCleanup(answers.close)
        cli = [design_cli(self.url, spec)
               for spec in ("c-two-tasks-t10.textproto", "a-one-task-t1.textproto")]
        for run in cli:
            self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(json.loads(cli[0].stdout)["design"], ["barrier-00-01", "barrier-10-11"])
        result, code = envdesign_client.design_result(
            os.path.join(RESTAURANT, "b-two-tasks-t1.textproto"), self.url, give_up_after_s=10)
        self.assertEqual(code, 0)
        bad_request(self, self.url)
        time.sleep(1)  # a second answer would have come by now

        python = answers.of(python_client())
        self.assertEqual(len(python), 2, python)  # the good request and the bad one
        cli_requests = {key: answers.of(key[0])[key] for key in answers.results
                        if key[0].startswith("client/")}
        self.assertEqual(len(cli_requests), 2, answers.results)
        sources = set()
        for request, (results, senders) in list(python.items()) + list(cli_requests.items()):
            self.assertEqual(results, 1, request)  # exactly one answer
            self.assertEqual(len(senders), 1, request)  # results and progress from one process
            sources |= senders
        self.assertEqual(len(sources), 1, sources)  # the same coordinator for all four
        self.assertEqual(self.log(0).count("| accepted:"), 3)  # the bad one is not accepted
        self.assertNotIn("accepted", self.log(1))
        for never in ("active: no coordinator", "taking over"):  # it stood by throughout
            self.assertNotIn(never, self.log(1))
        self.check_jobs(answers)

    def check_jobs(self, answers):
        """Jobs come from the active coordinator alone, and each is done by the planner it is
        addressed to: every evaluation names a planner the job went to, and each planner name
        is one process (with the old shared "planner-1", both clusters' planners did it)."""
        self.assertTrue(answers.jobs, "no job on the bus")
        self.assertTrue(answers.evaluations, "no evaluation on the bus")
        self.assertEqual({name for name, _ in answers.job_senders}, {self.coordinators[0]})
        self.assertEqual(len({source for _, source in answers.job_senders}), 1)
        for coordinator, job_id, planner, _ in answers.evaluations:
            self.assertEqual(coordinator, self.coordinators[0])
            self.assertIn(planner, answers.jobs[(coordinator, job_id)], (job_id, planner))
        by_planner = answers.processes_by_planner()
        self.assertLessEqual(set(by_planner), set(self.planners))
        for planner, sources in by_planner.items():
            self.assertEqual(len(sources), 1, planner)

    def test_status_shows_all_four_processes(self):
        rows, table = status_rows(self.url)
        named = sorted((r["name"], r["kind"], r["role"]) for r in rows)
        self.assertEqual(named, sorted([(self.coordinators[0], "coordinator", "active"),
                                        (self.coordinators[1], "coordinator", "standby"),
                                        (self.planners[0], "planner", ""),
                                        (self.planners[1], "planner", "")]))
        self.assertEqual(len({r["name"] for r in rows}), 4)  # no name is shared
        coordinators = [r for r in rows if r["kind"] == "coordinator"]
        active = next(r for r in coordinators if r["role"] == "active")
        standby = next(r for r in coordinators if r["role"] == "standby")
        self.assertLess(active["started_utime"], standby["started_utime"])  # the earlier start
        self.assertEqual(active["planners"], 2)  # both clusters' planners, by their own names
        lines = table.splitlines()
        for name in self.coordinators + self.planners:
            self.assertEqual(len([line for line in lines if f" {name} " in line]), 1, table)
        self.assertNotIn("services have this name", table)


class SharedNames(unittest.TestCase):
    """Two coordinators and two planners given one --name each, on purpose or by mistake: a
    request is still answered once, by the earlier coordinator, and `envdesign status` shows
    the four processes and says which names are shared."""
    url = port_url(3)

    def start(self, work, log_name, binary, name):
        log = os.path.join(work, log_name + ".log")
        with open(log, "w") as out:
            process = subprocess.Popen(
                [os.path.join(BUILD, "bin", binary), "--lcm-url", self.url, "--name", name],
                stdout=out, stderr=subprocess.STDOUT)
        self.addCleanup(process.wait)
        self.addCleanup(process.terminate)
        self.assertTrue(wait_for(log, "| on "), log)
        return log

    def test_one_answer_and_the_shared_names_in_status(self):
        work = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, work, True)
        logs = []
        for i in range(2):
            logs.append(self.start(work, f"coordinator-{i}", "envdesign-coordinator",
                                   "coordinator"))
            self.start(work, f"planner-{i}", "envdesign-planner", "planner-1")
            if i == 0:
                self.assertTrue(wait_for(logs[0], "active: no coordinator"), logs[0])
        self.assertTrue(wait_for(logs[1], "standing by: another coordinator named "
                                          "coordinator"), logs[1])
        answers = Answers(self.url)
        self.addCleanup(answers.close)
        run = design_cli(self.url, "c-two-tasks-t10.textproto")
        self.assertEqual(run.returncode, 0, run.stderr)
        self.assertEqual(json.loads(run.stdout)["design"], ["barrier-00-01", "barrier-10-11"])
        bad_request(self, self.url)
        time.sleep(1)  # a second answer would have come by now
        requests = {key: value for key, value in answers.results.items()
                    if key[0].startswith("client/") or key[0] == python_client()}
        self.assertEqual(len(requests), 2, answers.results)
        for request, sources in requests.items():
            self.assertEqual(len(sources), 1, request)
        self.assertEqual(len({s for sources in requests.values() for s in sources}), 1)

        rows, table = status_rows(self.url)
        named = sorted((r["name"], r["kind"], r["role"]) for r in rows)
        self.assertEqual(named, [("coordinator", "coordinator", "active"),
                                 ("coordinator", "coordinator", "standby"),
                                 ("planner-1", "planner", ""), ("planner-1", "planner", "")])
        lines = table.splitlines()
        self.assertEqual(len([line for line in lines if line.startswith("coordinator ")]), 2)
        self.assertEqual(len([line for line in lines if line.startswith("planner ")]), 2)
        for name in ("coordinator", "planner-1"):
            self.assertIn(f"  {name}: 2 services have this name (messages addressed to it reach "
                          "all of them); give each its own --name", lines)


class DefaultNames(unittest.TestCase):
    """Without --name every coordinator is ROLE/HOST/PID: two on one bus are two names, two
    rows, one active (the earlier) and no shared name."""
    url = port_url(1)

    def test_two_coordinators_without_names(self):
        work = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, work, True)
        processes, logs = [], []
        for i in range(2):
            logs.append(os.path.join(work, f"coordinator-{i}.log"))
            with open(logs[-1], "w") as log:
                processes.append(subprocess.Popen(
                    [os.path.join(BUILD, "bin", "envdesign-coordinator"), "--lcm-url", self.url],
                    stdout=log, stderr=subprocess.STDOUT))
            self.addCleanup(processes[-1].wait)
            self.addCleanup(processes[-1].terminate)
            self.assertTrue(wait_for(logs[-1], "| on "), logs[-1])
        names = [f"coordinator/{socket.gethostname()}/{p.pid}" for p in processes]
        self.assertTrue(wait_for(logs[1], f"standing by: coordinator {names[0]} started "
                                          "earlier"), logs[1])
        rows, table = status_rows(self.url)
        self.assertEqual(sorted((r["name"], r["role"]) for r in rows),
                         sorted([(names[0], "active"), (names[1], "standby")]))
        self.assertNotIn("services have this name", table)


class WhileDiscovering(unittest.TestCase):
    """A coordinator joining a bus listens before it speaks: a bad request sent while it is
    discovering (--discovery 3) is answered once, by the one already active, not by both."""
    url = port_url(2)

    def start(self, work, name, *flags):
        log = os.path.join(work, name + ".log")
        with open(log, "w") as out:
            process = subprocess.Popen(
                [os.path.join(BUILD, "bin", "envdesign-coordinator"), "--lcm-url", self.url,
                 "--name", name, *flags], stdout=out, stderr=subprocess.STDOUT)
        self.addCleanup(process.wait)
        self.addCleanup(process.terminate)
        return log

    def test_a_bad_request_is_answered_once(self):
        work = tempfile.mkdtemp()
        self.addCleanup(shutil.rmtree, work, True)
        first = self.start(work, "first")
        self.assertTrue(wait_for(first, "active: no coordinator"), first)
        second = self.start(work, "second", "--discovery", "3")
        self.assertTrue(wait_for(second, "| on "), second)
        answers = Answers(self.url)
        self.addCleanup(answers.close)
        with self.assertRaises(envdesign_client.RemoteError) as bad:
            envdesign_client.design(os.path.join(RESTAURANT, "a-one-task-t1.textproto"),
                                    self.url, ranking=-1, give_up_after_s=10)
        self.assertEqual(bad.exception.exit_code, 2)
        self.assertTrue(wait_for(second, "standing by: coordinator first started earlier"),
                        second)
        time.sleep(1)  # the second's discovery is over: had it held an answer, it is out
        with open(second) as f:
            if "malformed message on ENVDESIGN_REQUEST" not in f.read():  # checked: it was
                self.skipTest("the second heard the first before the request came")  # ~5%
        client = f"python-client/{socket.gethostname()}/{os.getpid()}"
        (results, senders), = answers.of(client).values()
        self.assertEqual(results, 1)
        self.assertEqual(len(senders), 1)


if __name__ == "__main__":
    unittest.main()
