#!/usr/bin/env python3
"""envdesign's Python client: the optimal design of a spec file from a running coordinator.

    envdesign-client SPEC [--connect URL] [--json] [--timeout S] [--time-limit S]
        [--max-design-size K] [--ranking N [--ranking-all]] [--search witness|exhaustive]
        [--prune none|relevant] [--heuristic H] [--key-file FILE]

prints what `envdesign design SPEC --connect URL` prints (envdesign_text.py), or with --json
the result as `envdesign design --json` writes it.

    import envdesign_client
    result = envdesign_client.design("spec.textproto", "udpm://239.255.76.67:7667?ttl=0")
    print(result["design"], result["objective"])

Installed by `sh clients/python/install.sh` (a venv with the message types), or run in the
repository as `python3 clients/python/envdesign_client.py` after a build.

Debian ships no LCM Python module, so this speaks LCM's UDP multicast protocol itself (small
and fragmented messages, stdlib sockets) and uses the classes lcm-gen writes for our types
(pure Python: build/python/envdesign, or $ENVDESIGN_PYTHON_TYPES). Like the C++ client it
inlines the PDDL files the spec names, re-sends the request while the coordinator is silent,
says it still waits every 2 s (the coordinator drops a request whose client went silent),
cancels it when its own timeout passes, and exits with SPEC.md's codes (3: no design has a
finite objective, with the reason). With a key file
(--key-file or $ENVDESIGN_KEY_FILE) it signs what it sends and takes only what the key signed
(envdesign_auth.py); results and progress count only from the coordinator that took the request.
"""
import argparse
import json
import math
import os
import random
import re
import socket
import struct
import sys
import time
import urllib.parse

import envdesign_auth
import envdesign_text

HERE = os.path.dirname(os.path.abspath(__file__))
for candidate in (os.environ.get("ENVDESIGN_PYTHON_TYPES", ""), HERE,  # HERE: installed
                  os.path.join(HERE, "..", "..", "build", "python"),
                  os.path.join(HERE, "..", "..", "share", "envdesign", "python")):
    if candidate and os.path.isdir(os.path.join(candidate, "envdesign")):
        sys.path.insert(0, candidate)
        break
try:
    from envdesign import (cancel_t, design_progress_t, design_request_t,  # noqa: E402
                           design_result_t, keepalive_t, spec_file_t, spec_t)
except ImportError:
    MISSING_TYPES = ("envdesign-client: the LCM message types (Python package 'envdesign') are "
                     "missing: install with clients/python/install.sh, or build the "
                     "repository (build/python) or set $ENVDESIGN_PYTHON_TYPES")
    if __name__ == "__main__":
        sys.exit(MISSING_TYPES)
    raise ImportError(MISSING_TYPES) from None

DEFAULT_URL = "udpm://239.255.76.67:7667?ttl=0"
KEEPALIVE_S = 2.0  # "still waiting", as common/bus/channels.h's CLIENT_KEEPALIVE_S
SHORT_MAGIC, FRAGMENT_MAGIC = 0x4C433032, 0x4C433033
SHORT_MAX = 1400      # LCM sends bigger messages as fragments
FRAGMENT_BYTES = 60000


class SpecError(Exception):
    """The spec or a file it names cannot be read (exit code 2)."""


class UrlError(ValueError):
    """The LCM URL cannot be used (exit code 2)."""


def parse_url(url):
    """(group, port, options) of a udpm:// URL; UrlError saying what is wrong otherwise."""
    parsed = urllib.parse.urlparse(url)
    if parsed.scheme != "udpm":
        raise UrlError(f"bad LCM URL '{url}': only udpm:// URLs are supported")
    try:
        port = parsed.port or 7667
        group = socket.inet_aton(parsed.hostname or "")
    except (ValueError, OSError):
        raise UrlError(f"bad LCM URL '{url}': expected udpm://GROUP:PORT?ttl=N, "
                       "GROUP an IPv4 multicast address") from None
    if not 224 <= group[0] <= 239:
        raise UrlError(f"bad LCM URL '{url}': {parsed.hostname} is not a multicast address "
                       "(224.0.0.0 to 239.255.255.255)")
    options = dict(urllib.parse.parse_qsl(parsed.query))
    try:
        int(options.get("ttl", 0)), int(options.get("recv_buf_size", 0))
    except ValueError:
        raise UrlError(f"bad LCM URL '{url}': ttl and recv_buf_size must be integers") from None
    return parsed.hostname, port, options


class UdpmBus:
    """LCM over UDP multicast (LCM's udpm:// provider), as far as a client needs it."""

    # Reassembly's bounds, so that forged fragments cannot grow our memory: no message
    # above MAX_MESSAGE_BYTES (4x what the bus carries reliably, PLATFORM.md), at most
    # MAX_PARTIALS messages in reassembly and MAX_BUFFERED_BYTES held by them, the least
    # recently touched going first, and none untouched for PARTIAL_EXPIRY_S.
    MAX_MESSAGE_BYTES = 16 << 20
    MAX_PARTIALS = 8
    MAX_BUFFERED_BYTES = 32 << 20
    PARTIAL_EXPIRY_S = 5.0

    def __init__(self, url, auth=None):
        self.auth = auth  # envdesign_auth.Auth, or None: unauthenticated
        self.group, self.port, options = parse_url(url)
        self.sequence = random.getrandbits(31)
        # Without keys, each message declares this process (the C++ bus's origin trailer,
        # common/bus/auth.h): the coordinator counts its requests as one client's.
        self.origin = random.getrandbits(64) or 1
        self.tx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.tx.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_TTL, int(options.get("ttl", 0)))
        self.tx.setsockopt(socket.IPPROTO_IP, socket.IP_MULTICAST_LOOP, 1)
        self.rx = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
        self.rx.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        self.rx.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF,
                           int(options.get("recv_buf_size", 4194304)))
        self.rx.bind(("", self.port))
        membership = struct.pack("4s4s", socket.inet_aton(self.group), socket.inet_aton("0.0.0.0"))
        self.rx.setsockopt(socket.IPPROTO_IP, socket.IP_ADD_MEMBERSHIP, membership)
        self.partial = {}  # (sender, sequence) -> _Partial, least recently touched first
        self.held = 0  # bytes held in self.partial

    def close(self):
        self.tx.close()
        self.rx.close()

    def publish_message(self, channel, message):
        """An LCM message: signed with keys, else followed by this process's origin."""
        payload = message.encode()
        if not self.auth:
            payload += struct.pack(">Q", self.origin) + b"EDO1"
        self.publish(channel, payload)

    def publish(self, channel, payload):
        """The bytes as given (signed with keys)."""
        if self.auth:
            payload = self.auth.sign(channel, payload)
        self.sequence = (self.sequence + 1) & 0xFFFFFFFF
        name = channel.encode() + b"\0"
        if 8 + len(name) + len(payload) <= SHORT_MAX:
            datagrams = [struct.pack(">II", SHORT_MAGIC, self.sequence) + name + payload]
        else:
            body = name + payload
            count = math.ceil(len(body) / FRAGMENT_BYTES)
            datagrams = []
            for i in range(count):
                piece = body[i * FRAGMENT_BYTES:(i + 1) * FRAGMENT_BYTES]
                offset = 0 if i == 0 else i * FRAGMENT_BYTES - len(name)  # in the payload
                datagrams.append(struct.pack(">IIIIHH", FRAGMENT_MAGIC, self.sequence,
                                             len(payload), offset, i, count) + piece)
        for datagram in datagrams:
            self.tx.sendto(datagram, (self.group, self.port))

    def receive(self, timeout):
        """The next whole message (channel, payload), or None when `timeout` passes."""
        end = time.monotonic() + timeout
        while True:
            left = end - time.monotonic()
            if left <= 0:
                return None
            self.rx.settimeout(left)
            try:
                datagram, sender = self.rx.recvfrom(70000)
            except socket.timeout:
                return None
            message = self._take(datagram, sender)
            if message and self.auth:
                payload = self.auth.verify(*message)
                message = (message[0], payload) if payload is not None else None
            if message:
                return message

    def _take(self, datagram, sender):
        if len(datagram) >= 8 and struct.unpack(">I", datagram[:4])[0] == SHORT_MAGIC:
            name, _, payload = datagram[8:].partition(b"\0")
            return name.decode(errors="replace"), payload
        if len(datagram) < 20 or struct.unpack(">I", datagram[:4])[0] != FRAGMENT_MAGIC:
            return None  # not LCM
        _, sequence, size, offset, number, count = struct.unpack(">IIIIHH", datagram[:20])
        if size > self.MAX_MESSAGE_BYTES or number >= count:
            return None
        now = time.monotonic()
        while self.partial:  # least recently touched first: expired ones lead
            key, oldest = next(iter(self.partial.items()))
            if now - oldest.touched < self.PARTIAL_EXPIRY_S:
                break
            self._drop(key)
        data, channel = datagram[20:], None
        if number == 0:
            name, _, data = data.partition(b"\0")
            if offset != 0:
                return None
            channel = name.decode(errors="replace")
        if offset + len(data) > size:
            return None
        key = (sender, sequence)
        entry = self.partial.get(key)
        if entry is None:
            # Like LCM, one message per sender in reassembly: a sender sends its fragments
            # in order, so its older message lost a fragment.
            for other in [k for k in self.partial if k[0] == sender]:
                self._drop(other)
            entry = self.partial[key] = _Partial(size, count)
        elif entry.size != size or entry.count != count or number in entry.pieces:
            return None  # contradicts what came before, or a repeat
        if channel is not None:
            entry.channel = channel
        entry.pieces[number] = (offset, data)
        entry.touched = now
        self.held += len(data)
        self.partial[key] = self.partial.pop(key)  # now the most recently touched
        if len(entry.pieces) == count:
            self._drop(key)
            payload, at = [], 0
            for piece_offset, piece in sorted(entry.pieces.values(), key=lambda p: p[0]):
                if piece_offset != at:
                    return None  # gaps or overlaps: not one message
                payload.append(piece)
                at += len(piece)
            return (entry.channel, b"".join(payload)) if at == size else None
        # Over a bound: the least recently touched go (not this one: it is the most recent,
        # and alone it holds at most MAX_MESSAGE_BYTES <= MAX_BUFFERED_BYTES).
        while len(self.partial) > self.MAX_PARTIALS or self.held > self.MAX_BUFFERED_BYTES:
            self._drop(next(iter(self.partial)))
        return None

    def _drop(self, key):
        self.held -= self.partial.pop(key).held()


class _Partial:
    """A message in reassembly: its fragments by number, as (offset in the payload, bytes)."""

    def __init__(self, size, count):
        self.size, self.count = size, count
        self.channel = None
        self.pieces = {}
        self.touched = 0.0

    def held(self):
        return sum(len(data) for _, data in self.pieces.values())


TOKEN = re.compile(r"""\s+|\#[^\n]*|(?P<id>[A-Za-z_][\w.]*)|(?P<str>(?:"(?:[^"\\\n]|\\.)*"\s*|'(?:[^'\\\n]|\\.)*'\s*)+)|(?P<open>[{<])|(?P<close>[}>])|.""")
STRING = re.compile(r""""((?:[^"\\]|\\.)*)"|'((?:[^'\\]|\\.)*)'""")


def named_paths(text, is_json):
    """[(field, path)] of the spec's robot_domain, human_domain and task problems."""
    if is_json:
        try:
            spec = json.loads(text)
        except ValueError:
            return []  # the coordinator says what is wrong
        found = [(f, spec.get(f) or spec.get(c)) for f, c in
                 (("robot_domain", "robotDomain"), ("human_domain", "humanDomain"))]
        for i, task in enumerate(spec.get("task", []) if isinstance(spec, dict) else []):
            if isinstance(task, dict):
                found.append((f"task[{i}].problem", task.get("problem")))
                found.append((f"task[{i}].human_problem",
                              task.get("human_problem") or task.get("humanProblem")))
        return [(f, p) for f, p in found if isinstance(p, str) and p]
    found, stack, tasks, name = [], [], 0, None
    for match in TOKEN.finditer(text):
        if match.group("id"):
            name = match.group("id")
        elif match.group("open"):
            tasks += 1 if not stack and name == "task" else 0
            stack.append(name)
            name = None
        elif match.group("close"):
            stack = stack[:-1]
            name = None
        elif match.group("str") and name:
            value = "".join(a or b for a, b in STRING.findall(match.group("str")))
            value = re.sub(r"\\(.)", r"\1", value)
            if not stack and name in ("robot_domain", "human_domain"):
                found.append((name, value))
            elif stack == ["task"] and name in ("problem", "human_problem"):
                found.append((f"task[{tasks - 1}].{name}", value))
            name = None
    return found


def bundle_spec(path):
    """The spec_t of a spec file: its text and every PDDL file it names."""
    try:
        with open(path) as f:
            text = f.read()
    except OSError as e:  # as the C++ CLI says it: the file, no line
        raise SpecError(f"{path}: error: cannot open file: {e.strerror}")
    spec = spec_t()
    spec.name, spec.text, spec.files = path, text, []
    seen = set()
    for field, relative in named_paths(text, path.endswith(".json")):
        if relative in seen:
            continue
        seen.add(relative)
        full = relative if os.path.isabs(relative) else os.path.join(os.path.dirname(path), relative)
        try:
            with open(full) as f:
                content = f.read()
        except OSError:
            raise SpecError(f"{path}:1:1: error: cannot open '{relative}' ({field}, looked for {full})")
        file = spec_file_t()
        file.path, file.content = relative, content
        spec.files.append(file)
    spec.num_files = len(spec.files)
    return spec


def number(value):
    """As the engine writes numbers: integral values as integers, infinity as "inf"."""
    if math.isinf(value):
        return "inf"
    return int(value) if value == math.floor(value) and abs(value) < 1e15 else value


def objective_json(t, explaining=False):
    out = {"objective": number(t.objective),
           "terms": {"inexplicability": number(t.inexplicability),
                     "design_cost": number(t.design_cost), "robot_cost": number(t.robot_cost)}}
    if explaining:  # robot_behaviour EXPLAINING (docs/behaviours-explaining.md)
        out["terms"]["explanation"] = number(t.explanation)
    return out


def task_json(t):
    out = {"name": t.name, "probability": t.probability, "ie": number(t.ie),
           "robot_cost": number(t.robot_cost), "human_plan_cost": number(t.human_plan_cost),
           "human_optimal_cost": number(t.human_optimal_cost)
           if t.has_human_optimal_cost else None,
           "plan": list(t.plan)}
    if t.has_explanation:  # the option taken and the explanation
        out["option"] = "explain" if t.explained else "act_explicably"
        out["explanation"] = list(t.explanation.differences) if t.explanation.found else None
        out["explicable_ie"] = number(t.explicable_ie)
        out["robot_optimal_cost"] = number(t.explanation.robot_optimal_cost)
    return out


def result_json(r):
    """SPEC.md's JSON of a design_result_t (the keys the C++ client writes)."""
    out = {"status": r.status}
    if r.status == "unsolvable":  # why no design has a finite objective
        out["reason"] = r.error
    explaining = any(t.has_explanation for t in r.tasks)
    if r.has_design:
        out["design"] = list(r.design)
        out.update(objective_json(r.best, explaining))
        out["tasks"] = [task_json(t) for t in r.tasks]
    else:
        out.update({"design": None, "objective": None, "terms": None, "tasks": []})
    out["baseline"] = objective_json(r.baseline, explaining) if r.has_baseline else None
    c = r.counters
    for key in ("configurations_evaluated", "planner_runs", "seconds", "configurations_total",
                "configurations_abandoned", "configurations_skipped", "configurations_pruned",
                "task_evaluations", "cache_hits", "groundings_skipped", "planner_seconds"):
        out[key] = getattr(c, key)
    out["cluster"] = {k: getattr(c, k) for k in ("jobs_sent", "jobs_resent", "duplicates_ignored",
                                                 "planners_used", "transport_seconds", "job_seconds",
                                                 "stored_answers")}
    out["limit_reached"] = bool(r.limit_reached)
    if r.change:  # a re-evaluation: what changed and why
        out["change"] = r.change
    if r.num_warnings:  # what the user should read beside the answer
        out["warnings"] = list(r.warnings)
    return out


class RemoteError(Exception):
    def __init__(self, exit_code, message):
        super().__init__(message)
        self.exit_code = exit_code


def design(spec_path, url=None, **options):
    """SPEC.md's result (a dict, as `envdesign design --json` prints it) of designing
    `spec_path` on the coordinator at `url` (None: $LCM_DEFAULT_URL, else LCM's default).
    A search a limit stopped gives status "best_found" and limit_reached true. `options` are
    design_message()'s. Raises SpecError, UrlError or envdesign_auth.KeyFileError (exit code 2),
    RemoteError (its exit_code: 1, 2 or 4), OSError (the network)."""
    return design_result(spec_path, url, **options)[0]


def design_result(spec_path, url=None, *args, **options):
    """(result dict, exit code): design() with SPEC.md's exit code (0, or 4 for a result a
    time limit or timeout stopped)."""
    message, code = design_message(spec_path, url, *args, **options)
    return result_json(message), code


def design_message(spec_path, url=None, time_limit_s=-1, max_design_size=-1, prune="none",
                   heuristic="lmcut", timeout_s=0, on_progress=None, resend_after_s=3,
                   give_up_after_s=30, key_file=None, ranking=0, search="witness",
                   ranking_all=False):
    """(design_result_t, exit code): the coordinator's result message itself, which
    envdesign_text.result_text() prints as the C++ CLI does. Raises as design() does."""
    path = envdesign_auth.key_file_path(key_file)
    auth = envdesign_auth.Auth(envdesign_auth.load_key_file(path)) if path else None
    request = design_request_t()
    request.spec = bundle_spec(spec_path)
    request.utime = int(time.time() * 1e6)
    request.request_id = random.getrandbits(62) | 1
    request.sender = f"python-client/{socket.gethostname()}/{os.getpid()}"
    request.time_limit_s, request.max_design_size = float(time_limit_s), int(max_design_size)
    request.prune = {"none": 0, "relevant": 1}[prune]
    request.heuristic = {"lmcut": 0, "hmax": 1, "blind": 2}[heuristic]
    request.search = {"witness": 0, "exhaustive": 1}[search]
    request.ranking = int(ranking)
    request.ranking_all = 1 if ranking_all else 0
    bus = UdpmBus(url or os.environ.get("LCM_DEFAULT_URL") or DEFAULT_URL, auth)
    try:
        return _wait_for_result(bus, request, timeout_s, on_progress, resend_after_s, give_up_after_s)
    finally:
        bus.close()


def _keep_alive(bus, request):
    """Tells the coordinator we still wait: it drops requests whose client went silent."""
    keepalive = keepalive_t()
    keepalive.utime, keepalive.request_id = int(time.time() * 1e6), request.request_id
    keepalive.sender = request.sender
    bus.publish_message("ENVDESIGN_KEEPALIVE", keepalive)


def _wait_for_result(bus, request, timeout_s, on_progress, resend_after_s, give_up_after_s):
    start = sent = heard = kept_alive = time.monotonic()
    bus.publish_message("ENVDESIGN_REQUEST", request)
    cancelled = False
    taken_by = [None]  # the coordinator that took the request
    while True:
        message = bus.receive(0.05)
        now = time.monotonic()
        if message:
            result = _ours(message, request, on_progress, taken_by)
            if result is not None:
                if result.status == "error":
                    raise RemoteError(result.exit_code, result.error)
                if cancelled and result.exit_code == 0:
                    result.exit_code = 4
                return result, result.exit_code
            if message[0] == "ENVDESIGN_PROGRESS":
                heard = now
        if timeout_s and now - start > timeout_s and not cancelled:
            cancel = cancel_t()
            cancel.utime, cancel.request_id, cancel.sender = int(time.time() * 1e6), request.request_id, request.sender
            cancel.reason = "the client's timeout passed"
            bus.publish_message("ENVDESIGN_CANCEL", cancel)
            cancelled, start = True, now
        elif cancelled and now - start > 5:
            raise RemoteError(4, f"timeout: no result within {timeout_s} s")
        if now - heard > give_up_after_s:
            raise RemoteError(1, f"no coordinator answered on udpm://{bus.group}:{bus.port}")
        if now - sent > resend_after_s and now - heard > resend_after_s:
            taken_by[0] = None  # it went silent: whoever takes the request now
            bus.publish_message("ENVDESIGN_REQUEST", request)
            sent = kept_alive = now
        if not cancelled and now - kept_alive >= KEEPALIVE_S:
            _keep_alive(bus, request)
            kept_alive = now


def _from_taker(m, request, taken_by):
    """`m` answers our request, from the coordinator that took it (the first to answer)."""
    if m.request_id != request.request_id or m.client != request.sender:
        return False
    taken_by[0] = taken_by[0] or m.sender
    return m.sender == taken_by[0]


def _ours(message, request, on_progress, taken_by):
    """The result if `message` is ours; calls on_progress for our progress."""
    channel, payload = message
    try:
        if channel == "ENVDESIGN_RESULT":
            r = design_result_t.decode(payload)
            if _from_taker(r, request, taken_by):
                return r
        elif channel == "ENVDESIGN_PROGRESS":
            p = design_progress_t.decode(payload)
            if _from_taker(p, request, taken_by) and on_progress:
                on_progress(p)
    except (ValueError, struct.error):
        pass  # not our types: somebody else's traffic, or garbage
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("spec")
    parser.add_argument("--connect", default=None, help="LCM URL of the coordinator")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--timeout", type=float, default=0)
    parser.add_argument("--time-limit", type=float, default=-1)
    parser.add_argument("--max-design-size", type=int, default=-1)
    parser.add_argument("--ranking", type=int, default=0,
                        help="list the N best designs, best first (0: the best alone)")
    parser.add_argument("--ranking-all", action="store_true",
                        help="rank designs with a modification that does not pay for itself too")
    parser.add_argument("--search", choices=["witness", "exhaustive"], default="witness")
    parser.add_argument("--prune", choices=["none", "relevant"], default="none")
    parser.add_argument("--heuristic", choices=["lmcut", "hmax", "blind"], default="lmcut")
    parser.add_argument("--key-file", default=None,
                        help="bus keys (default: $ENVDESIGN_KEY_FILE; deploy/LAN.md)")
    args = parser.parse_args()

    def progress(p):
        if sys.stderr.isatty():
            sys.stderr.write(f"\r\033[K{p.done}/{p.total} configurations, best {p.best_objective:g}, "
                             f"{p.planners} planner(s)")

    try:
        result, code = design_message(args.spec, args.connect, args.time_limit,
                                      args.max_design_size, args.prune, args.heuristic,
                                      args.timeout, progress, key_file=args.key_file,
                                      ranking=args.ranking, search=args.search,
                                      ranking_all=args.ranking_all)
    except SpecError as e:  # "FILE:LINE:COL: error: ..." as the other commands say it
        print(e, file=sys.stderr)
        return 2
    except (UrlError, envdesign_auth.KeyFileError) as e:
        print(f"envdesign-client: {e}", file=sys.stderr)
        return 2
    except RemoteError as e:
        print(e, file=sys.stderr)
        return e.exit_code
    except OSError as e:  # no multicast route, no network
        print(f"envdesign-client: the bus cannot be used: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("envdesign-client: interrupted", file=sys.stderr)
        return 130
    if sys.stderr.isatty():
        sys.stderr.write("\r\033[K")
    if args.json:
        print(json.dumps(result_json(result), sort_keys=True))
    else:
        sys.stdout.write(envdesign_text.result_text(result))
    if code == 4:
        print("envdesign-client: the time limit stopped the search; the design is the best found",
              file=sys.stderr)
    return code


if __name__ == "__main__":
    sys.exit(main())
