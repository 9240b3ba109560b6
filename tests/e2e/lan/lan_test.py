#!/usr/bin/env python3
"""The LAN test (issue 11): a small site in network namespaces (lan_site.py) — coordinator,
planner-1, planner-2, bridge, arrivals publisher and client each on a host of its own, an
observer beside them — talking LCM udpm with ttl=1 and Cyclone DDS bound to the hosts' veth.

  undisturbed: the client asks for the design of SPEC while the publisher replays arrivals
      of serve-g2 (25/s, until the end) to the bridge, which re-designs the drift spec
      through the coordinator: its D moves from the spec's 0.9/0.1 to 0/1, the same D
      whatever the timing, so the same design and objective in both runs.
  disturbed, fresh state: every host sends through the udp shim (5% loss, 5% duplication,
      10% reordering); planner-2's cable is pulled for 5 s during the search and plugged
      back; the coordinator is SIGKILLed mid-search and restarted on its --state-dir; the
      client re-sends; the bridge keeps running.

Checked: the same design and objective for the client and for the bridge's final design;
0 evaluations asked again after the restart (jobs the restarted coordinator sent, less its
re-sends, less the records it added to the state file: a job for an evaluation stored before
the kill adds none); a repeat request sends 0 jobs. Exit code 77 (skipped) when namespaces
cannot be made here, with the reason.

    lan_test.py --build build --shim build/lib/libenvdesign_udp_shim.so [--keep]
                [--spec SPEC] [--seed N] [--markdown OUT.md]
"""
import argparse
import json
import os
import re
import signal
import sqlite3
import sys
import tempfile
import time

import lan_site

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
HOSTS = ["observer", "coordinator", "planner-1", "planner-2", "bridge", "arrivals", "client"]
PORT, DOMAIN = 7711, 11
DRIFT_SPEC = os.path.join(ROOT, "tests/arrivals/data/restaurant-drift.textproto")
ARRIVAL_RATE = 25
HOLD_MS = 20  # a reordered datagram waits this long at most for one to overtake it
FAULTS = {"ENVDESIGN_SHIM_LOSS": "5", "ENVDESIGN_SHIM_DUPLICATE": "5",
          "ENVDESIGN_SHIM_REORDER": "10", "ENVDESIGN_SHIM_HOLD_MS": str(HOLD_MS)}
SAME = ("status", "design", "objective", "terms", "baseline", "tasks", "limit_reached")
URL = f"udpm://239.255.76.67:{PORT}?ttl=1&recv_buf_size=4194304"


class Failed(Exception):
    """A wait that timed out or a step that went wrong: the test fails, saying which."""


class Watch:
    """What the observer hears: planners' heartbeats and the bridge's estimates."""

    def __init__(self, build):
        os.environ["ENVDESIGN_PYTHON_TYPES"] = os.path.join(build, "python")
        sys.path.insert(0, os.path.join(ROOT, "clients", "python"))
        import envdesign_client
        from envdesign import planner_heartbeat_t, task_distribution_t
        self.types = {"ENVDESIGN_HEARTBEAT": planner_heartbeat_t,
                      "ENVDESIGN_TASK_DISTRIBUTION": task_distribution_t}
        self.bus = envdesign_client.UdpmBus(URL)
        self.reset()

    def reset(self):
        self.done = {}   # planner -> jobs_done in its last heartbeat
        self.beats = {}  # planner -> heartbeats heard
        self.estimate = None

    def pump(self, seconds):
        end = time.monotonic() + seconds
        while (left := end - time.monotonic()) > 0:
            message = self.bus.receive(left)
            if not message or message[0] not in self.types:
                continue
            try:
                m = self.types[message[0]].decode(message[1])
            except ValueError:
                continue
            if message[0] == "ENVDESIGN_HEARTBEAT":
                self.done[m.sender] = m.jobs_done
                self.beats[m.sender] = self.beats.get(m.sender, 0) + 1
            elif m.problem_id == "restaurant":
                self.estimate = m

    def until(self, condition, timeout, what):
        end = time.monotonic() + timeout
        while not condition():
            if time.monotonic() > end:
                raise Failed(f"timed out after {timeout} s waiting for {what}")
            self.pump(0.05)

    def jobs_done(self):
        return sum(self.done.values())

    def bridge_design(self):
        """The bridge's design in force, its objective and its D, as it last published them."""
        e = self.estimate
        return {"design": list(e.design), "objective": round(e.objective, 9),
                "reference": dict(zip(e.tasks, (round(p, 9) for p in e.reference)))}


def all_serve_g2(tasks, d):
    """True if D is all serve-g2: the D of the arrivals, the bridge's goal."""
    return dict(zip(tasks, d)).get("serve-g2") == 1


def records(state_dir):
    """Records in the coordinator's evaluation file, read as any other program would."""
    db = sqlite3.connect(os.path.join(state_dir, "evaluations.db"))
    try:
        return db.execute("SELECT count(*) FROM records").fetchone()[0]
    finally:
        db.close()


def shim_counts(work):
    """The shim's counts summed over every process that ran with it."""
    total = {}
    for name in os.listdir(work):
        if name.startswith("shim-"):
            with open(os.path.join(work, name)) as f:
                for pair in f.read().split():
                    key, _, value = pair.partition("=")
                    if value.isdigit():
                        total[key] = total.get(key, 0) + int(value)
    return total


class Run:
    """One run of the site: services started on their hosts, with or without the shim."""

    def __init__(self, site, watch, args, work, name, faults):
        self.site, self.watch, self.args, self.name = site, watch, args, name
        self.dir = os.path.join(work, name)
        self.state = os.path.join(self.dir, "state")
        os.makedirs(self.state)
        self.faults = faults
        self.seeds = {host: args.seed * 100 + i for i, host in enumerate(HOSTS)}
        self.restarts = 0

    def env(self, host):
        env = dict(os.environ, CYCLONEDDS_URI=f"file://{self.args.cyclone}")
        for inherited in ("LCM_DEFAULT_URL", "ENVDESIGN_KEY_FILE", "LD_PRELOAD"):
            env.pop(inherited, None)  # the site's URL, no keys, faults only when asked
        if self.faults:
            env.update(FAULTS, LD_PRELOAD=self.args.shim,
                       ENVDESIGN_SHIM_SEED=str(self.seeds[host]),
                       ENVDESIGN_SHIM_COUNTS=os.path.join(self.dir, f"shim-{host}-%p.txt"))
        return env

    def start(self, host, argv, log=None, stdout=None):
        binary = os.path.join(self.args.build, "bin", argv[0])
        return self.site.start(host, [binary, *argv[1:]],
                               os.path.join(self.dir, (log or host) + ".log"),
                               env=self.env(host), stdout=stdout)

    def log(self, name):
        with open(os.path.join(self.dir, name + ".log")) as f:
            return f.read()

    def wait_log(self, name, text, timeout):
        end = time.monotonic() + timeout
        while text not in self.log(name):
            if time.monotonic() > end:
                raise Failed(f"{name} never logged '{text}' within {timeout} s")
            self.watch.pump(0.05)

    def start_coordinator(self):
        log = "coordinator" if not self.restarts else f"coordinator-{self.restarts}"
        self.coordinator = self.start("coordinator", [
            "envdesign-coordinator", "--lcm-url", URL, "--name", "coordinator",
            "--state-dir", self.state, "--planner-timeout", "2", "--lost-after", "0.5"], log)
        for planner in ("planner-1", "planner-2"):
            self.wait_log(log, f"planner {planner} joined", 30)

    def start_services(self):
        self.watch.reset()
        self.planners = [self.start(p, ["envdesign-planner", "--lcm-url", URL, "--name", p])
                         for p in ("planner-1", "planner-2")]
        self.start_coordinator()
        self.bridge = self.start("bridge", [
            "envdesign-bridge", "--problem", f"restaurant={DRIFT_SPEC}", "--redesign",
            "coordinator", "--domain", str(DOMAIN), "--lcm-url", URL, "--name", "bridge",
            "--estimator", "window:100", "--min-samples", "50", "--answer-timeout", "3"])

    def start_work(self):
        """The client's request and the arrivals, at once. The arrivals go on until the end:
        the bridge notices a request that went unanswered (lost on the way there or back)
        only when an arrival comes after its --answer-timeout."""
        self.started = time.monotonic()
        self.client_out = open(os.path.join(self.dir, "client.json"), "w")
        self.client = self.start("client", ["envdesign", "design", self.args.spec, "--json",
                                            "--connect", URL], stdout=self.client_out)
        self.arrivals = self.start("arrivals", [
            "envdesign-arrivals", "--replay", self.args.replay, "--problem", "restaurant",
            "--site", "dock-1", "--domain", str(DOMAIN), "--rate", str(ARRIVAL_RATE), "--repeat",
            "1000", "--wait-bridge", "30"])

    def client_result(self, client, out, timeout=240):
        self.watch.until(lambda: client.poll() is not None, timeout, "the client's result")
        out.close()
        if client.returncode != 0:
            raise Failed(f"{self.name}: the client exited {client.returncode}:\n"
                         + self.log("client"))
        with open(out.name) as f:
            return json.load(f)

    def wait_bridge_design(self):
        """Waits for the bridge's design it is for the arrivals' D and nothing is pending."""
        def settled():
            e = self.watch.estimate
            return e is not None and e.state == 0 and all_serve_g2(e.tasks, e.reference)
        self.watch.until(settled, 60, "the bridge's design for the arrivals' D")

    def bridge_final(self):
        """The bridge's design, and whether every arrival published reached it, once the
        publisher is stopped."""
        self.wait_bridge_design()
        self.arrivals.send_signal(signal.SIGTERM)
        self.watch.until(lambda: self.arrivals.poll() is not None, 30, "the publisher's end")
        published = re.search(r"published (\d+) arrivals", self.log("arrivals"))
        if self.arrivals.returncode != 0 or not published:
            raise Failed(f"envdesign-arrivals exited {self.arrivals.returncode}:\n"
                         + self.log("arrivals"))
        published = int(published.group(1))
        self.watch.until(lambda: self.watch.estimate.estimated >= published, 30,
                         f"the bridge's estimate of all {published} arrivals")
        e = self.watch.estimate
        return self.watch.bridge_design(), {"published": published, "estimated": e.estimated,
                                            "gaps": e.sequence_gaps}

    def repeat(self):
        out = open(os.path.join(self.dir, "repeat.json"), "w")
        client = self.start("client", ["envdesign", "design", self.args.spec, "--json",
                                       "--connect", URL], "repeat", stdout=out)
        return self.client_result(client, out)


def undisturbed(run):
    run.start_services()
    run.start_work()
    result = run.client_result(run.client, run.client_out)
    seconds = time.monotonic() - run.started
    bridge, arrivals = run.bridge_final()
    run.watch.pump(0.5)
    return {"result": result, "seconds": seconds, "bridge": bridge, "arrivals": arrivals,
            "planner_jobs": run.watch.jobs_done()}


def disturbed(run, jobs):
    """`jobs`: the undisturbed search's, to place the partition and the kill in this one."""
    w = run.watch
    run.start_services()
    run.start_work()
    w.until(lambda: w.jobs_done() >= 0.15 * jobs, 120, "15% of the search's jobs")
    beats = w.beats.get("planner-2", 0)
    run.site.unplug("planner-2")
    w.pump(5)
    run.site.plug("planner-2")
    # The observer saw the cable pulled: at most a heartbeat in flight got through.
    heard_unplugged = w.beats.get("planner-2", 0) - beats
    w.until(lambda: w.beats.get("planner-2", 0) > beats + heard_unplugged, 30,
            "planner-2's heartbeats after the cable was plugged back")
    # The bridge's re-design (through this coordinator) is done before the kill, so every
    # job the restarted coordinator sends is the client's.
    run.wait_bridge_design()
    w.until(lambda: w.jobs_done() >= 0.5 * jobs, 120, "half the search's jobs")
    if run.client.poll() is not None:
        raise Failed("the search ended before the kill: use a longer spec")
    killed_done = w.jobs_done()
    run.coordinator.send_signal(signal.SIGKILL)
    run.coordinator.wait()
    killed_at = time.monotonic() - run.started
    stored_at_kill = records(run.state)
    run.restarts += 1
    run.start_coordinator()
    result = run.client_result(run.client, run.client_out)
    seconds = time.monotonic() - run.started
    bridge, arrivals = run.bridge_final()
    w.pump(0.5)
    stored = records(run.state)
    counters = result["cluster"]
    asked_again = counters["jobs_sent"] - counters["jobs_resent"] - (stored - stored_at_kill)
    repeat = run.repeat()
    return {"result": result, "seconds": seconds, "bridge": bridge, "arrivals": arrivals,
            "planner_jobs": w.jobs_done(), "killed_at": killed_at, "killed_done": killed_done,
            "stored_at_kill": stored_at_kill, "stored": stored, "asked_again": asked_again,
            "repeat": repeat, "unplugged_beats": heard_unplugged,
            "planner2_silent": "planner planner-2 went silent" in run.log("coordinator"),
            "shim": shim_counts(run.dir)}


def check(a, b):
    """(name, passed, detail) for every claim of the test."""
    ra, rb = a["result"], b["result"]
    checks = [(f"client: {key} as undisturbed", ra[key] == rb[key],
               "" if ra[key] == rb[key] else f"{ra[key]} vs {rb[key]}") for key in SAME]
    checks += [
        ("bridge: final design, objective and D as undisturbed", a["bridge"] == b["bridge"],
         f"{a['bridge']} vs {b['bridge']}"),
        ("bridge: every arrival published was estimated, no sequence gaps",
         all(r["estimated"] == r["published"] and r["gaps"] == 0
             for r in (a["arrivals"], b["arrivals"])), f"{a['arrivals']}, {b['arrivals']}"),
        ("0 evaluations asked again after the restart", b["asked_again"] == 0,
         f"{b['result']['cluster']['jobs_sent']} sent, {b['result']['cluster']['jobs_resent']} "
         f"re-sent, {b['stored'] - b['stored_at_kill']} records added"),
        ("the state file had evaluations at the kill", b["stored_at_kill"] > 0,
         str(b["stored_at_kill"])),
        ("a repeat request sends 0 jobs", b["repeat"]["cluster"]["jobs_sent"] == 0,
         str(b["repeat"]["cluster"]["jobs_sent"])),
        ("a repeat request: the same design", all(b["repeat"][k] == ra[k] for k in SAME),
         str(b["repeat"]["design"])),
        ("partition: planner-2 unheard while unplugged", b["unplugged_beats"] <= 1,
         f"{b['unplugged_beats']} heartbeats heard"),
        ("partition: the coordinator dropped planner-2", b["planner2_silent"], ""),
    ]
    shim = b["shim"]
    for key in ("dropped", "duplicated", "reordered"):
        checks.append((f"shim: datagrams {key}", shim.get(key, 0) > 0, str(shim.get(key, 0))))
    return checks


def markdown(args, a, b, checks):
    ra, rb, shim = a["result"], b["result"], b["shim"]
    spec = os.path.relpath(args.spec, ROOT)

    def design(names):
        return "{" + ", ".join(names) + "}"

    def bridge(run):
        return f"{design(run['bridge']['design'])} ({run['bridge']['objective']:.4f})"

    return "\n".join([
        f"Spec `{spec}` (client), `{os.path.relpath(DRIFT_SPEC, ROOT)}` (bridge; arrivals "
        f"of serve-g2 at {ARRIVAL_RATE}/s: {a['arrivals']['published']} undisturbed, "
        f"{b['arrivals']['published']} disturbed, all estimated); seed {args.seed}.", "",
        "| run | client design | objective | jobs sent | re-sent | planner jobs (all) | "
        "s to result | bridge design (objective) |", "|---|---|---|---|---|---|---|---|",
        f"| undisturbed | {design(ra['design'])} | {ra['objective']:.6f} | "
        f"{ra['cluster']['jobs_sent']} | {ra['cluster']['jobs_resent']} | {a['planner_jobs']} "
        f"| {a['seconds']:.1f} | {bridge(a)} |",
        f"| disturbed | {design(rb['design'])} | {rb['objective']:.6f} | "
        f"{rb['cluster']['jobs_sent']} (after the restart) | {rb['cluster']['jobs_resent']} | "
        f"{b['planner_jobs']} | {b['seconds']:.1f} | {bridge(b)} |", "",
        f"Disturbed: coordinator SIGKILLed at {b['killed_at']:.1f} s with "
        f"{b['killed_done']} planner jobs done and {b['stored_at_kill']} evaluations stored; "
        f"the restarted one added {b['stored'] - b['stored_at_kill']} records; evaluations "
        f"asked again: {b['asked_again']}; repeat request: "
        f"{b['repeat']['cluster']['jobs_sent']} jobs.", "",
        f"Shim (all hosts): {shim.get('datagrams', 0)} UDP datagrams, {shim.get('dropped', 0)} "
        f"dropped, {shim.get('duplicated', 0)} duplicated, {shim.get('reordered', 0)} "
        f"reordered (+{shim.get('delayed', 0)} held {HOLD_MS} ms with none after).", "",
        f"{sum(ok for _, ok, _ in checks)} of {len(checks)} checks passed.", ""])


def cyclone_config(work):
    """deploy/cyclonedds-lan.xml with the hosts' interface named."""
    with open(os.path.join(ROOT, "deploy", "cyclonedds-lan.xml")) as f:
        text = f.read()
    named = text.replace('autodetermine="true"', 'name="lan0"')
    if named == text:
        raise Failed("deploy/cyclonedds-lan.xml has no autodetermined NetworkInterface to name")
    path = os.path.join(work, "cyclonedds.xml")
    with open(path, "w") as f:
        f.write(named)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--build", required=True)
    parser.add_argument("--shim", required=True)
    parser.add_argument("--spec", default=os.path.join(
        ROOT, "tests/data/paper/blocksworld/12/design-t10.textproto"))
    parser.add_argument("--seed", type=int, default=11)
    parser.add_argument("--keep", action="store_true", help="keep the logs even if it passes")
    parser.add_argument("--markdown", help="write the numbers as a Markdown table here")
    args = parser.parse_args()
    args.build, args.spec = os.path.abspath(args.build), os.path.abspath(args.spec)
    reason = lan_site.why_not_here()
    if reason:
        print(f"SKIPPED: {reason}")
        return 77
    lan_site.remove_stale_namespaces()
    work = tempfile.mkdtemp(prefix="envdesign-lan-")
    args.cyclone = cyclone_config(work)
    args.replay = os.path.join(work, "arrivals.csv")
    with open(args.replay, "w") as f:
        f.write("task\n" + "serve-g2\n" * 100)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("lan_test: terminated"))
    ok = False
    try:
        with lan_site.Site(HOSTS) as site:
            site.enter("observer")
            watch = Watch(args.build)
            a = undisturbed(Run(site, watch, args, work, "undisturbed", faults=False))
            print(f"undisturbed: {a['result']['cluster']['jobs_sent']} jobs, "
                  f"{a['seconds']:.1f} s", flush=True)
            for p in site.processes:
                p.terminate()
            for p in site.processes:
                p.wait()
            site.processes.clear()
            b = disturbed(Run(site, watch, args, work, "disturbed", faults=True),
                          a["result"]["cluster"]["jobs_sent"])
        checks = check(a, b)
        for name, passed, detail in checks:
            print(f"{'ok  ' if passed else 'FAIL'} {name}" + (f": {detail}" if detail else ""))
        table = markdown(args, a, b, checks)
        print(table)
        if args.markdown:
            with open(args.markdown, "w") as f:
                f.write(table)
        ok = all(passed for _, passed, _ in checks)
    except (Failed, lan_site.SiteError) as e:
        print(f"FAIL: {e}")
    finally:
        if ok and not args.keep:
            import shutil
            shutil.rmtree(work, ignore_errors=True)
        else:
            print(f"logs kept in {work}")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
