"""Bus authentication for the Python client: the trailer of common/bus/auth.h, stdlib only.

A signed message is the LCM bytes, then 68 bytes: key id (8, NUL-padded), sender (u64,
random per process), counter (u64), utime (i64, microseconds), HMAC-SHA256 (32) over
u16 len(channel) | channel | LCM bytes | the 32 bytes before the MAC, then b"EDA1".
Key files: "KEY_ID HEX_SECRET" a line, mode 0600 (common/bus/key_file.h, deploy/LAN.md).
"""
import hashlib
import hmac
import os
import random
import stat
import struct
import time

TRAILER_SIZE = 68
MAGIC = b"EDA1"
TOLERANCE_US = 30_000_000
WINDOW = 256
MAX_SENDERS = 1024
REASONS = ("unauthenticated", "unknown-key", "bad-mac", "stale", "replayed")


class KeyFileError(Exception):
    """The key file cannot be used (exit code 2)."""


def key_file_path(flag):
    """The key file to use: `flag`, else $ENVDESIGN_KEY_FILE, else None."""
    return flag or os.environ.get("ENVDESIGN_KEY_FILE") or None


def parse_keys(text, source):
    keys, ids = [], set()
    for number, line in enumerate(text.splitlines(), 1):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        where = f"{source}:{number}"
        if len(words) != 2:
            raise KeyFileError(f"{where}: expected 'KEY_ID HEX_SECRET'")
        key_id, hex_secret = words
        if not (1 <= len(key_id) <= 8) or not all(c.isalnum() or c in "._-" for c in key_id):
            raise KeyFileError(f"{where}: key id '{key_id}' is not 1-8 of [A-Za-z0-9._-]")
        try:
            secret = bytes.fromhex(hex_secret)
        except ValueError:
            raise KeyFileError(f"{where}: the secret of key '{key_id}' is not hexadecimal")
        if not 32 <= len(secret) <= 64:
            raise KeyFileError(f"{where}: the secret of key '{key_id}' has {len(secret)} bytes; "
                               "use 32 to 64 (openssl rand -hex 32)")
        if key_id in ids:
            raise KeyFileError(f"{where}: key id '{key_id}' appears twice")
        ids.add(key_id)
        keys.append((key_id.encode().ljust(8, b"\0"), secret))
    if not keys:
        raise KeyFileError(f"{source}: no key (expected lines 'KEY_ID HEX_SECRET')")
    if len(keys) > 8:
        raise KeyFileError(f"{source}: more than 8 keys")
    return keys


def load_key_file(path):
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError as e:
        raise KeyFileError(f"{path}: cannot open the key file: {e.strerror}")
    with os.fdopen(fd, "rb") as f:
        st = os.fstat(f.fileno())
        if not stat.S_ISREG(st.st_mode):
            raise KeyFileError(f"{path}: the key file is not a regular file")
        if st.st_mode & 0o077:
            raise KeyFileError(f"{path}: the key file is accessible by group or others (mode "
                               f"{st.st_mode & 0o777:o}); chmod 600 it")
        if st.st_uid not in (os.geteuid(), 0):
            raise KeyFileError(f"{path}: the key file belongs to another user")
        return parse_keys(f.read(65537).decode(errors="replace"), path)


def _mac(secret, channel, payload, header):
    name = channel.encode()
    return hmac.new(secret, struct.pack(">H", len(name)) + name + payload + header,
                    hashlib.sha256).digest()


class Auth:
    """Signs what this process sends, verifies what it hears; counts drops per channel."""

    def __init__(self, keys):
        self.keys = keys  # [(padded id, secret)]; the first signs
        self.sender = random.getrandbits(64) or 1
        self.counter = 0
        self.seen = {}  # sender -> [newest counter, window bits, last utime]
        self.forgotten_until = 0
        self.drops = {}  # (channel, reason) -> count

    def sign(self, channel, payload):
        self.counter += 1
        key_id, secret = self.keys[0]
        header = key_id + struct.pack(">QQq", self.sender, self.counter, int(time.time() * 1e6))
        return payload + header + _mac(secret, channel, payload, header) + MAGIC

    def verify(self, channel, data):
        """The LCM bytes of a message that passes, else None (and the drop is counted)."""
        reason = self._check(channel, data)
        if reason is None:
            return data[:-TRAILER_SIZE]
        self.drops[(channel, reason)] = self.drops.get((channel, reason), 0) + 1
        return None

    def _check(self, channel, data):
        if len(data) < TRAILER_SIZE or data[-4:] != MAGIC:
            return "unauthenticated"
        payload, trailer = data[:-TRAILER_SIZE], data[-TRAILER_SIZE:]
        secret = next((s for key_id, s in self.keys if key_id == trailer[:8]), None)
        if secret is None:
            return "unknown-key"
        if not hmac.compare_digest(_mac(secret, channel, payload, trailer[:32]), trailer[32:64]):
            return "bad-mac"
        sender, counter, utime = struct.unpack(">QQq", trailer[8:32])
        if abs(time.time() * 1e6 - utime) > TOLERANCE_US:
            return "stale"
        return None if self._new(sender, counter, utime) else "replayed"

    def _new(self, sender, counter, utime):
        seen = self.seen.get(sender)
        if seen is None:
            if utime <= self.forgotten_until:
                return False
            if len(self.seen) >= MAX_SENDERS:  # forget the least recently heard
                oldest = next(iter(self.seen))
                self.forgotten_until = max(self.forgotten_until, self.seen.pop(oldest)[2])
            self.seen[sender] = [counter, 1, utime]
            return True
        newest, window, last = seen
        if counter > newest:
            shift = counter - newest
            window = 1 if shift >= WINDOW else ((window << shift) | 1) & ((1 << WINDOW) - 1)
            newest = counter
        elif newest - counter >= WINDOW or window >> (newest - counter) & 1:
            return False
        else:
            window |= 1 << (newest - counter)
        del self.seen[sender]  # re-insert: dict order is the order last heard
        self.seen[sender] = [newest, window, max(last, utime)]
        return True
